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
        // The program's own file is in its folder: the text sent is that file (edited or
        // not), not a second copy of its programs.
        if (dir.is_string()) session.addLibrary(dir.get<std::string>(), name);
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
    return out;
  } catch (const SetupError& e) {
    return failure(std::string("setup error: ") + e.what());
  } catch (const std::exception& e) {
    return failure(e.what());
  }
}

}  // namespace ncvm::server
