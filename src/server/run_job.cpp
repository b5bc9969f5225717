#include "server/run_job.hpp"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <vector>

#include "app/session.hpp"
#include "exec/executor.hpp"
#include "server/safe_path.hpp"
#include "server/step_recorder.hpp"

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

// The programs of a lib folder, only those inside its root (symlinks followed).
void addConfinedLibrary(Session& session, const std::string& dir,
                        const std::vector<NamedFolder>& roots) {
  std::filesystem::path confine = dir;
  for (const auto& r : roots)
    if (r.name != "macros" && isInside(r.path, dir)) confine = r.path;
  session.store().addFolder(
      dir, [&confine](const std::string& file) { return isInside(confine, file); });
}

}  // namespace

nlohmann::json runJob(const nlohmann::json& request) {
  if (!request.is_object() || !request.contains("program") || !request["program"].is_string())
    return failure("the request needs \"program\": the program text");
  const std::string& text = request["program"].get_ref<const std::string&>();
  RunCaps caps = capsFrom(request.value("caps", nlohmann::json()));
  if (text.size() > caps.maxProgramBytes)
    return failure("program too large: " + std::to_string(text.size()) +
                   " bytes, the server accepts " + std::to_string(caps.maxProgramBytes));
  std::string name = request.value("name", std::string("program.nc"));
  if (name.empty() || name.size() > 255) name = "program.nc";

  const std::vector<NamedFolder> folders = namedFolders(request);
  try {
    Setup setup = defaultSetup();
    if (request.contains("setup") && request["setup"].is_string())
      setup = parseSetup(request["setup"].get_ref<const std::string&>(),
                         request.value("setup_name", "setup.toml"));
    confineSetupFiles(setup, request);
    // The server's caps bound whatever the setup asks for.
    Limits& lim = setup.limits;
    lim.maxBlocks = std::min(lim.maxBlocks, caps.maxBlocks);
    lim.maxTimeSeconds = std::min(lim.maxTimeSeconds, caps.maxSimSeconds);
    lim.maxTraceBytes = std::min(lim.maxTraceBytes, caps.maxTraceBytes);
    lim.maxFileBytes = std::min(lim.maxFileBytes, caps.maxProgramBytes);

    Session session(setup);
    session.addProgramText(text, name);
    if (!session.main()) return failure("no program in the text");
    if (request.contains("libs") && request["libs"].is_array())
      for (const auto& dir : request["libs"])
        if (dir.is_string()) addConfinedLibrary(session, dir.get<std::string>(), folders);
    session.addBundledMacros();

    // A setup with [stock] gets its stock simulated, as `ncvm run --stock-out` would, but
    // no files are written: the final stock goes back in the answer.
    if (session.setup().stock.present) {
      session.simulateStock("");
      session.keepViewerStock(kViewerGrid);
    }

    StepRecorder recorder(session.files(), session.setup(), session.setup().limits.maxTraceBytes);
    session.setInspector([&](Executor& e) { recorder.attach(&e); });
    Session::Result r = session.run(&recorder);
    recorder.attach(nullptr);

    nlohmann::json out;
    out["ok"] = true;
    out["name"] = name;
    out["state"] = std::move(r.state);
    out["trace"] = recorder.trace();
    out["steps"] = std::move(recorder.steps());
    out["check"] = session.check();
    out["printed"] = r.printed;
    out["load_warnings"] = session.store().warnings();
    out["machine"] = {{"kind", session.setup().kind == MachineKind::Lathe ? "lathe" : "mill"},
                      {"axes", session.setup().reportedAxes()}};
    // The final stock (web/src/stock.js draws it); its analysis is state["stock"].
    if (!r.viewerStock.is_null()) out["stock"] = std::move(r.viewerStock);
    renameFolders(out, folders);
    return out;
  } catch (const SetupError& e) {
    return failure(withFolderNames(std::string("setup error: ") + e.what(), folders));
  } catch (const std::exception& e) {
    return failure(withFolderNames(e.what(), folders));
  }
}

}  // namespace ncvm::server
