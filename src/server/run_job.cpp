#include "server/run_job.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <vector>

#include "app/session.hpp"
#include "exec/executor.hpp"
#include "server/safe_path.hpp"
#include "server/setup_layers.hpp"
#include "server/step_recorder.hpp"
#include "server/stock_snapshots.hpp"
#include "server/viewer_stream.hpp"
#include "server/viewer_tools.hpp"

namespace ncvm::server {

nlohmann::json capsJson(const RunCaps& caps) {
  return {{"max_program_bytes", caps.maxProgramBytes},
          {"max_blocks", caps.maxBlocks},
          {"max_sim_seconds", caps.maxSimSeconds},
          {"max_trace_bytes", caps.maxTraceBytes}};
}

namespace {

// A mill stock reaches the browser as at most 256 x 256 heights (about 0.6 MB of JSON).
constexpr int kViewerGrid = 256;
// The timeline's stock: at most 64 snapshots (a mill's 256 KB each, 16 MB in all).
constexpr size_t kStockSnapshots = 64;

RunCaps capsFrom(const nlohmann::json& j) {
  RunCaps c;
  if (!j.is_object()) return c;
  c.maxProgramBytes = j.value("max_program_bytes", c.maxProgramBytes);
  c.maxBlocks = j.value("max_blocks", c.maxBlocks);
  c.maxSimSeconds = j.value("max_sim_seconds", c.maxSimSeconds);
  c.maxTraceBytes = j.value("max_trace_bytes", c.maxTraceBytes);
  return c;
}

// The files a setup names (target.polyline, target.height_map) are read only inside the
// folders the server vouches for: a path relative to one of them and staying inside it.
// A request's setup comes from a web page, so "/etc/passwd" or "../../x" would otherwise
// make the worker open any file the server can read.
void confineSetupFiles(Setup& setup, const nlohmann::json& request) {
  std::vector<std::string> folders;
  auto it = request.find("setup_dir");
  if (it == request.end()) it = request.find("libs");
  if (it != request.end() && it->is_string()) folders.push_back(it->get<std::string>());
  if (it != request.end() && it->is_array())
    for (const auto& d : *it)
      if (d.is_string()) folders.push_back(d.get<std::string>());
  for (auto [file, name] : {std::pair{&setup.target.polyline, "target.polyline"},
                            std::pair{&setup.target.heightMap, "target.height_map"}}) {
    if (file->empty()) continue;
    std::optional<std::filesystem::path> inside;
    for (const auto& dir : folders)
      if ((inside = resolveInside(dir, *file))) break;
    if (!inside)
      throw SetupError(std::string(name) + ": \"" + *file +
                           "\" is not a file of the program's folder (the server reads files "
                           "only inside its folders, by a path relative to the program)",
                       name, setup.target.line);
    *file = inside->string();
  }
}

nlohmann::json failure(const std::string& message) {
  return {{"ok", false}, {"error", message}};
}

// A folder of the server's machine and how answers name it.
struct NamedFolder {
  std::filesystem::path path;  // canonical
  std::string name;
};

std::vector<NamedFolder> namedFolders(const nlohmann::json& request) {
  std::vector<NamedFolder> out;
  if (!request.is_object()) return out;
  std::error_code ec;
  auto it = request.find("roots");
  if (it != request.end() && it->is_array())
    for (const auto& r : *it)
      if (r.is_object() && r.value("path", "") != "" && r.value("name", "") != "")
        if (auto p = std::filesystem::canonical(r["path"].get<std::string>(), ec); !ec)
          out.push_back({p, r["name"].get<std::string>()});
  if (std::string macros = bundledMacrosFolder(); !macros.empty())
    if (auto p = std::filesystem::canonical(macros, ec); !ec) out.push_back({p, "macros"});
  return out;
}

// `text` with every server folder replaced by its name (file names, error messages).
std::string withFolderNames(std::string text, const std::vector<NamedFolder>& folders) {
  for (const auto& f : folders) {
    const std::string abs = f.path.string();
    for (size_t at = text.find(abs); at != std::string::npos;
         at = text.find(abs, at + f.name.size()))
      text.replace(at, abs.size(), f.name);
  }
  return text;
}

// Every string of an answer (file names in the state, the trace's text, the checks, the
// warnings) with the server's folders named.
void renameFolders(nlohmann::json& j, const std::vector<NamedFolder>& folders) {
  if (j.is_string())
    j = withFolderNames(j.get<std::string>(), folders);
  else if (j.is_structured())
    for (auto& v : j) renameFolders(v, folders);
}

// The programs of a lib folder, only those inside its root (symlinks followed), but the
// file named `except` (the program's own file: the text sent is that file).
void addConfinedLibrary(Session& session, const std::string& dir, std::string_view except,
                        const std::vector<NamedFolder>& roots) {
  std::filesystem::path confine = dir;
  for (const auto& r : roots)
    if (r.name != "macros" && isInside(r.path, dir)) confine = r.path;
  session.store().addFolder(
      dir, except, [&confine](const std::string& file) { return isInside(confine, file); });
}

// A session ready to run the request's program, or a failure message.
struct Prepared {
  std::unique_ptr<Session> session;
  std::string name;
  std::string error;
};

// The program text: the request's "program", or the file "program_path" (a path the server
// resolved inside its folders), read here so that a large file never passes through JSON.
std::optional<std::string> programText(const nlohmann::json& request, const RunCaps& caps,
                                       std::string& error) {
  if (request.contains("program") && request["program"].is_string())
    return request["program"].get<std::string>();
  if (!request.contains("program_path") || !request["program_path"].is_string()) {
    error = "the request needs \"program\": the program text";
    return std::nullopt;
  }
  const std::string path = request["program_path"].get<std::string>();
  std::error_code ec;
  uint64_t size = std::filesystem::file_size(path, ec);
  if (ec) {
    error = "cannot read the program";
    return std::nullopt;
  }
  if (size > caps.maxProgramBytes) {
    error = tooLarge(size, caps.maxProgramBytes);
    return std::nullopt;
  }
  std::ifstream in(path, std::ios::binary);
  std::string text(size, '\0');
  if (!in.read(text.data(), static_cast<std::streamsize>(size))) {
    error = "cannot read the program";
    return std::nullopt;
  }
  return text;
}

Prepared prepare(const nlohmann::json& request, const std::vector<NamedFolder>& folders) {
  Prepared p;
  if (!request.is_object()) {
    p.error = "the request needs \"program\": the program text";
    return p;
  }
  RunCaps caps = capsFrom(request.value("caps", nlohmann::json()));
  std::optional<std::string> text = programText(request, caps, p.error);
  if (!text) return p;
  if (text->size() > caps.maxProgramBytes) {
    p.error = tooLarge(text->size(), caps.maxProgramBytes);
    return p;
  }
  p.name = request.value("name", std::string("program.nc"));
  if (p.name.empty() || p.name.size() > 255) p.name = "program.nc";

  Setup setup = defaultSetup();
  if (request.contains("setup_layers") && request["setup_layers"].is_array())
    setup = layeredSetup(request["setup_layers"]);  // a preset, then the job, ...
  else if (request.contains("setup") && request["setup"].is_string())
    setup = parseSetup(request["setup"].get_ref<const std::string&>(),
                       request.value("setup_name", "setup.toml"));
  confineSetupFiles(setup, request);
  // The server's caps bound whatever the setup asks for.
  Limits& lim = setup.limits;
  lim.maxBlocks = std::min(lim.maxBlocks, caps.maxBlocks);
  lim.maxTimeSeconds = std::min(lim.maxTimeSeconds, caps.maxSimSeconds);
  lim.maxTraceBytes = std::min(lim.maxTraceBytes, caps.maxTraceBytes);
  lim.maxFileBytes = std::min(lim.maxFileBytes, caps.maxProgramBytes);

  p.session = std::make_unique<Session>(setup);
  Session& session = *p.session;
  session.addProgramText(*text, p.name);
  text.reset();
  if (!session.main()) {
    p.session.reset();
    p.error = "no program in the text";
    return p;
  }
  if (request.contains("libs") && request["libs"].is_array())
    for (const auto& dir : request["libs"])
      // The program's own file is in its folder: the text sent is that file (edited or
      // not), not a second copy of its programs.
      if (dir.is_string()) addConfinedLibrary(session, dir.get<std::string>(), p.name, folders);
  session.addBundledMacros();

  // A setup with [stock] gets its stock simulated, as `ncvm run --stock-out` would, but
  // no files are written: the final stock goes back in the answer.
  if (session.setup().stock.present) {
    session.simulateStock("");
    session.keepViewerStock(kViewerGrid);
  }
  return p;
}

// What both answers carry besides the timeline.
void finalParts(nlohmann::json& out, Session& session, Session::Result& r,
                const std::string& name) {
  out["ok"] = true;
  out["name"] = name;
  out["state"] = std::move(r.state);
  out["check"] = session.check();
  out["printed"] = r.printed;
  out["load_warnings"] = session.store().warnings();
  out["machine"] = {{"kind", session.setup().kind == MachineKind::Lathe ? "lathe" : "mill"},
                    {"axes", session.setup().reportedAxes()}};
  // The physical tools, drawn at the tool's place (web/src/tool_shape.js).
  out["tools"] = viewerTools(session.setup());
  // The final stock (web/src/stock.js draws it); its analysis is state["stock"].
  if (!r.viewerStock.is_null()) out["stock"] = std::move(r.viewerStock);
}

}  // namespace

std::string tooLarge(uint64_t bytes, uint64_t limit) {
  auto mb = [](uint64_t b) { return std::to_string((b + (1u << 20) - 1) >> 20); };
  return "program too large: " + std::to_string(bytes) + " bytes (" + mb(bytes) +
         " MB), the server accepts " + std::to_string(limit) + " bytes (" + mb(limit) +
         " MB; ncvm serve --max-program-mb raises it)";
}

nlohmann::json runJob(const nlohmann::json& request) {
  const std::vector<NamedFolder> folders = namedFolders(request);
  try {
    Prepared p = prepare(request, folders);
    if (!p.session) return failure(p.error);
    Session& session = *p.session;
    StepRecorder recorder(session.files(), session.setup(), session.setup().limits.maxTraceBytes);
    session.setInspector([&](Executor& e) { recorder.attach(&e); });
    Session::Result r = session.run(&recorder);
    recorder.attach(nullptr);

    nlohmann::json out;
    finalParts(out, session, r, p.name);
    out["trace"] = recorder.trace();
    out["steps"] = std::move(recorder.steps());
    renameFolders(out, folders);
    return out;
  } catch (const SetupError& e) {
    return failure(withFolderNames(std::string("setup error: ") + e.what(), folders));
  } catch (const std::exception& e) {
    return failure(withFolderNames(e.what(), folders));
  }
}

void runViewerJob(const nlohmann::json& request, const std::function<void(std::string_view)>& out) {
  std::unique_ptr<ViewerStream> stream;
  const std::vector<NamedFolder> folders = namedFolders(request);
  auto fail = [&](const std::string& raw) {
    const std::string message = withFolderNames(raw, folders);
    // Whatever was streamed stays valid: the end frame says why it stopped.
    out(frame(FrameKind::End,
              failure(message).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)));
  };
  try {
    Prepared p = prepare(request, folders);
    if (!p.session) return fail(p.error);
    Session& session = *p.session;
    stream = std::make_unique<ViewerStream>(session.files(), session.setup(),
                                            session.setup().limits.maxTraceBytes, out);
    stream->renameText([&](std::string text) { return withFolderNames(std::move(text), folders); });
    session.setInspector([&](Executor& e) { stream->attach(&e); });
    // "stock_every": the stock along the timeline, a snapshot every N moves to start with
    // (stock_snapshots.hpp); the page asks for it.
    std::unique_ptr<StockSnapshots> snapshots;
    if (session.setup().stock.present && request.contains("stock_every") &&
        request["stock_every"].is_number_integer() && request["stock_every"].get<int64_t>() > 0) {
      snapshots = std::make_unique<StockSnapshots>(
          kViewerGrid, request["stock_every"].get<uint64_t>(), kStockSnapshots);
      session.watchStock([&](StockModel& m, uint64_t moves) { snapshots->offer(m, moves); });
    }
    Session::Result r = session.run(stream.get());
    stream->attach(nullptr);
    nlohmann::json tail;
    finalParts(tail, session, r, p.name);
    renameFolders(tail, folders);
    if (snapshots) {
      for (const std::string& f : snapshots->frames()) out(f);
      tail["stock_snapshots"] = {{"every", snapshots->every()}, {"count", snapshots->count()}};
    }
    stream->finish(std::move(tail));
  } catch (const SetupError& e) {
    fail(std::string("setup error: ") + e.what());
  } catch (const std::exception& e) {
    fail(e.what());
  }
}

}  // namespace ncvm::server
