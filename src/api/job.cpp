// The public Job over the engine's Session (app/session.hpp), as the ncvm command drives it
// (src/cli/main.cpp: makeSetup, loadPrograms, runOne, checkCommand).
#include "ncvm/job.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <variant>
#include <vector>

#include "api/data_folder.hpp"
#include "api/event_adapter.hpp"
#include "app/session.hpp"
#include "core/version.hpp"
#include "machine/setup.hpp"
#include "ncvm/ncvm.hpp"

namespace ncvm::api {

Error::Error(const std::string& what) : std::runtime_error(what) {}
Error::~Error() = default;

std::string version() {
  return versionText();
}
std::string dataFolder() {
  return findDataFolder();
}

namespace {

struct ProgramText {
  std::string text, name;
};
struct ProgramFile {
  std::string path;
};
struct ProgramFolder {
  std::string path;
};
using ProgramSource = std::variant<ProgramText, ProgramFile, ProgramFolder>;

// Every failure of the engine that is not an alarm, as one exception type, worded as the
// ncvm command prints it (src/cli/command_line.hpp, commandError).
template <typename F>
auto translated(F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const Error&) {
    throw;
  } catch (const SetupError& e) {
    throw Error("setup error: " + setupErrorText(e));
  } catch (const std::filesystem::filesystem_error& e) {
    throw Error(fmt::format("{}: {}", e.path1().string(), e.code().message()));
  } catch (const std::exception& e) {
    throw Error(e.what());
  }
}

EndReason publicEnd(ncvm::EndReason r) {
  switch (r) {
    case ncvm::EndReason::M30:
      return EndReason::M30;
    case ncvm::EndReason::M02:
      return EndReason::M02;
    case ncvm::EndReason::M99:
      return EndReason::M99;
    case ncvm::EndReason::Alarm:
      return EndReason::Alarm;
    case ncvm::EndReason::Eof:
      return EndReason::EndOfFile;
    case ncvm::EndReason::Limit:
      return EndReason::Limit;
  }
  return EndReason::EndOfFile;
}

Location locationOf(const SourceLoc& loc, const SourceFiles& files) {
  return Location{files.name(loc.file), static_cast<int>(loc.line), static_cast<int>(loc.col)};
}

Location locationOf(const nlohmann::json& j) {
  return Location{j.value("file", std::string()), j.value("line", 0), j.value("col", 0)};
}

std::string dumpJson(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

}  // namespace

std::string endReasonName(EndReason reason) {
  // One mapping between the public and the engine's ends (publicEnd), one set of names (the
  // state JSON's).
  for (ncvm::EndReason r : {ncvm::EndReason::M30, ncvm::EndReason::M02, ncvm::EndReason::M99,
                            ncvm::EndReason::Alarm, ncvm::EndReason::Eof, ncvm::EndReason::Limit})
    if (publicEnd(r) == reason) return ncvm::endReasonName(r);
  return "?";
}

struct Job::Impl {
  Setup setup = defaultSetup();
  std::vector<ProgramSource> programs;
  bool macros = true;

  // A fresh Session for each run or check: the setup decides how the programs are read.
  std::unique_ptr<Session> session() const {
    auto s = std::make_unique<Session>(setup);
    for (const auto& p : programs) {
      if (const auto* t = std::get_if<ProgramText>(&p))
        s->addProgramText(t->text, t->name);
      else if (const auto* f = std::get_if<ProgramFile>(&p))
        s->addProgramFile(f->path);
      else
        s->addLibrary(std::get<ProgramFolder>(p).path);
    }
    if (macros) {
      const std::string data = findDataFolder();
      if (!data.empty()) s->addLibrary((std::filesystem::path(data) / "macros").string());
    }
    return s;
  }
};

Job::Job() : impl_(std::make_unique<Impl>()) {}
Job::~Job() = default;
Job::Job(Job&&) noexcept = default;
Job& Job::operator=(Job&&) noexcept = default;

void Job::loadSetup(const std::string& path) {
  translated([&] { loadSetupInto(impl_->setup, path); });
}

void Job::loadPreset(const std::string& name) {
  const std::string path = presetPath(name);
  if (path.empty())
    throw Error(fmt::format("no preset {} (presets/{}.toml under {})", name, name,
                            findDataFolder().empty() ? "no data folder" : findDataFolder()));
  loadSetup(path);
}

void Job::set(const std::string& keyValue) {
  translated([&] { applySetting(impl_->setup, keyValue); });
}

void Job::addProgramText(std::string_view text, const std::string& name) {
  impl_->programs.emplace_back(ProgramText{std::string(text), name});
}

void Job::addProgramFile(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw Error(fmt::format("{}: no such program file", path));
  impl_->programs.emplace_back(ProgramFile{path});
}

void Job::addFolder(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::is_directory(path, ec))
    throw Error(fmt::format("{}: no such folder", path));
  impl_->programs.emplace_back(ProgramFolder{path});
}

void Job::useBundledMacros(bool on) {
  impl_->macros = on;
}

RunResult Job::run(EventHandler* events) {
  return translated([&] {
    auto session = impl_->session();
    RunResult out;
    for (const auto& w : session->store().warnings()) out.warnings.push_back({"", w, {}});
    std::unique_ptr<EventAdapter> adapter;
    if (events) adapter = std::make_unique<EventAdapter>(*events, session->files());
    Session::Result r = session->run(adapter.get());
    const SourceFiles& files = session->files();
    out.end = publicEnd(r.end);
    if (r.alarm)
      out.alarm = Alarm{r.alarm->code, r.alarm->text, locationOf(r.alarm->loc, files), r.alarm->n};
    for (const auto& w : r.warnings)
      out.warnings.push_back({w.code, w.text, locationOf(w.loc, files)});
    out.stats.blocks = r.stats.blocks;
    out.stats.moves = r.stats.moves;
    out.stats.rapidLength = r.stats.rapidLength;
    out.stats.feedLength = r.stats.feedLength;
    out.stats.simpleTime = r.stats.time;
    if (session->setup().timing.dynamic && r.timing)
      out.stats.modelledTime = r.timing->total().model;
    out.stateJson = dumpJson(r.state);
    out.printed = r.printed;
    return out;
  });
}

CheckResult Job::check() {
  return translated([&] {
    auto session = impl_->session();
    nlohmann::json report = session->check();
    CheckResult out;
    for (const auto& a : report["alarms"]) {
      Alarm alarm{a.value("code", std::string()), a.value("text", std::string()), locationOf(a),
                  std::nullopt};
      if (a.contains("n") && a["n"].is_number_integer()) alarm.n = a["n"].get<int64_t>();
      out.alarms.push_back(std::move(alarm));
    }
    for (const auto& w : report["warnings"])
      out.warnings.push_back(
          {w.value("code", std::string()), w.value("text", std::string()), locationOf(w)});
    out.json = dumpJson(report);
    return out;
  });
}

}  // namespace ncvm::api
