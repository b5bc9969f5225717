// The ncvm command: run, check, and the generated reference tables (alarms, codes).
// Exit status: 0 normal end, 3 alarm, 2 usage or setup error.
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <thread>

#include "app/machine_state.hpp"
#include "app/session.hpp"
#include "core/alarm.hpp"
#include "exec/gcode_table.hpp"
#include "report/atomic_file.hpp"
#include "report/trace_writer.hpp"

namespace {

using namespace ncvm;

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitAlarm = 3;

struct CommonOptions {
  std::vector<std::string> programs;
  std::string setupPath;
  std::vector<std::string> libs;
  std::vector<std::string> sets;
  bool noMacros = false;
};

void addCommon(CLI::App* cmd, CommonOptions& o) {
  cmd->add_option("PROGRAM", o.programs, "program file(s); the first file's first program runs")->required();
  cmd->add_option("--setup", o.setupPath, "machine and job setup (TOML, docs/setup-format.md)");
  cmd->add_option("--lib", o.libs, "folder of programs for M98/G65 calls (repeatable)");
  cmd->add_option("--set", o.sets, "override a setting: 3401#0=1, DPI=1, block_skip.1=true, limits.max_blocks=1000");
  cmd->add_flag("--no-macros", o.noMacros, "do not load the bundled macros/ folder");
}

Setup makeSetup(const CommonOptions& o) {
  Setup s = o.setupPath.empty() ? defaultSetup() : loadSetup(o.setupPath);
  for (const auto& kv : o.sets) applySetting(s, kv);
  return s;
}

void loadPrograms(Session& session, const CommonOptions& o) {
  for (const auto& p : o.programs) session.addProgramFile(p);
  for (const auto& l : o.libs) session.addLibrary(l);
  if (!o.noMacros) session.addBundledMacros();
}

std::string alarmLine(const Alarm& a, const SourceFiles& files) {
  std::string s = fmt::format("{}:{}:{}: {} {}", files.name(a.loc.file), a.loc.line, a.loc.col, a.code, a.text);
  if (a.n) s += fmt::format(" (N{})", *a.n);
  return s;
}

std::string hms(double seconds) {
  auto total = static_cast<int64_t>(seconds);
  return fmt::format("{}:{:02d}:{:05.2f}", total / 3600, total / 60 % 60, seconds - static_cast<double>(total / 60 * 60));
}

// One run; what it would print goes to `out` (stdout) and `err` (stderr), so batch runs on
// several threads can print each program's report whole, in command-line order.
int runOne(const CommonOptions& o, const std::string& tracePath, const std::string& statePath,
           const std::string& outputPath, const std::string& machineStatePath, bool quiet, std::string& out,
           std::string& err) {
  auto outAt = std::back_inserter(out);
  auto errAt = std::back_inserter(err);
  Session session(makeSetup(o));
  loadPrograms(session, o);
  for (const auto& w : session.store().warnings()) fmt::format_to(errAt, "ncvm: warning: {}\n", w);

  std::unique_ptr<AtomicFile> traceFile;
  std::unique_ptr<TraceWriter> trace;
  if (!tracePath.empty()) {
    traceFile = std::make_unique<AtomicFile>(tracePath);
    trace = std::make_unique<TraceWriter>(session.files(), traceFile->get(), session.setup().limits.maxTraceBytes,
                                          session.setup().reportedAxes());
  }
  nlohmann::json memory;
  bool haveMemory = false;
  if (!machineStatePath.empty() && std::filesystem::exists(machineStatePath)) {
    std::ifstream in(machineStatePath);
    try {
      memory = nlohmann::json::parse(in);
    } catch (const std::exception& e) {
      throw std::runtime_error(machineStatePath + ": " + e.what());
    }
    haveMemory = true;
  }
  Session::Result r = session.run(trace.get(), haveMemory ? &memory : nullptr);
  // The control keeps its memory whatever way the run ended, alarms included.
  if (!machineStatePath.empty()) writeFileAtomic(machineStatePath, r.machineState.dump(2) + "\n");
  if (trace) {
    trace->flush();
    trace.reset();
    traceFile->commit();
  }
  if (!statePath.empty()) writeFileAtomic(statePath, r.state.dump(2) + "\n");
  std::string dprnt = !outputPath.empty() ? outputPath : session.setup().dprntPath;
  if (!r.printed.empty()) {
    if (dprnt.empty())
      err += "ncvm: warning: DPRNT output discarded (give --output FILE or output.dprnt)\n";
    else
      writeFileAtomic(dprnt, r.printed);
  }

  const Program* main = session.main();
  if (!quiet) {
    fmt::format_to(outAt, "ncvm: {} ({}) ended: {}\n", session.files().name(main->loc.file), main->label,
                   endReasonName(r.end));
    fmt::format_to(outAt, "  blocks {}, moves {}, path {:.3f} (rapid {:.3f}, feed {:.3f}), cycle time {} (length/feed)\n",
                   r.stats.blocks, r.stats.moves, r.stats.rapidLength + r.stats.feedLength, r.stats.rapidLength,
                   r.stats.feedLength, hms(r.stats.time));
    for (const auto& w : r.warnings)
      fmt::format_to(outAt, "{}:{}:{}: {} {}\n", session.files().name(w.loc.file), w.loc.line, w.loc.col, w.code, w.text);
    if (!tracePath.empty()) fmt::format_to(outAt, "  trace: {}\n", tracePath);
    if (!statePath.empty()) fmt::format_to(outAt, "  state: {}\n", statePath);
    if (!r.printed.empty() && !dprnt.empty()) fmt::format_to(outAt, "  output: {}\n", dprnt);
  }
  if (r.alarm) {
    fmt::format_to(outAt, "{}\n", alarmLine(*r.alarm, session.files()));
    return kExitAlarm;
  }
  return kExitOk;
}

int runCommand(const CommonOptions& o, const std::string& tracePath, const std::string& statePath,
               const std::string& outputPath, const std::string& machineStatePath, bool quiet) {
  std::string out, err;
  int rc = 0;
  try {
    rc = runOne(o, tracePath, statePath, outputPath, machineStatePath, quiet, out, err);
  } catch (...) {
    std::fputs(err.c_str(), stderr);
    throw;
  }
  std::fputs(err.c_str(), stderr);
  std::fputs(out.c_str(), stdout);
  return rc;
}

// `ncvm run --batch A.nc B.nc ...`: every file is a program of its own, run on its own
// thread (--jobs, default all cores). --trace, --state and --output name folders; each
// program writes STEM.jsonl, STEM.json and STEM.txt there. Reports are printed in
// command-line order; the exit status is the worst of the runs (2 > 3 > 0).
int batchCommand(const CommonOptions& o, const std::string& traceDir, const std::string& stateDir,
                 const std::string& outputDir, const std::string& machineStatePath, bool quiet,
                 unsigned jobs) {
  if (!machineStatePath.empty())
    throw std::runtime_error("--machine-state cannot be shared by the programs of a batch");
  const size_t n = o.programs.size();
  std::vector<std::string> stems(n);
  for (size_t k = 0; k < n; ++k) {
    stems[k] = std::filesystem::path(o.programs[k]).stem().string();
    for (size_t j = 0; j < k; ++j)
      if (stems[j] == stems[k])
        throw std::runtime_error(fmt::format("{} and {}: batch outputs would share the name {}",
                                             o.programs[j], o.programs[k], stems[k]));
  }
  for (const std::string* dir : {&traceDir, &stateDir, &outputDir})
    if (!dir->empty()) std::filesystem::create_directories(*dir);
  auto in = [](const std::string& dir, const std::string& stem, const char* ext) {
    return dir.empty() ? std::string() : (std::filesystem::path(dir) / (stem + ext)).string();
  };
  std::vector<std::string> outs(n), errs(n);
  std::vector<int> codes(n, kExitOk);
  std::atomic<size_t> next{0};
  auto worker = [&] {
    for (size_t k = next++; k < n; k = next++) {
      CommonOptions one = o;
      one.programs = {o.programs[k]};
      try {
        codes[k] = runOne(one, in(traceDir, stems[k], ".jsonl"), in(stateDir, stems[k], ".json"),
                          in(outputDir, stems[k], ".txt"), {}, quiet, outs[k], errs[k]);
      } catch (const SetupError& e) {
        errs[k] += fmt::format("ncvm: setup error: {}{}\n", e.what(),
                               e.line ? fmt::format(" (line {})", e.line) : "");
        codes[k] = kExitUsage;
      } catch (const std::exception& e) {
        errs[k] += fmt::format("ncvm: {}: {}\n", o.programs[k], e.what());
        codes[k] = kExitUsage;
      }
    }
  };
  if (jobs == 0) jobs = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 0; t < std::min<size_t>(jobs, n); ++t) pool.emplace_back(worker);
  for (auto& t : pool) t.join();
  int rc = kExitOk;
  for (size_t k = 0; k < n; ++k) {
    std::fputs(errs[k].c_str(), stderr);
    std::fputs(outs[k].c_str(), stdout);
    if (codes[k] == kExitUsage || (codes[k] == kExitAlarm && rc == kExitOk)) rc = codes[k];
  }
  return rc;
}

int checkCommand(const CommonOptions& o, bool json) {
  Session session(makeSetup(o));
  loadPrograms(session, o);
  nlohmann::json report = session.check();
  if (json) {
    fmt::print("{}\n", report.dump(2));
  } else {
    for (const char* kind : {"alarms", "warnings"})
      for (const auto& a : report[kind])
        fmt::print("{}:{}:{}: {} {}\n", a["file"].get<std::string>(), a["line"].get<int>(), a["col"].get<int>(),
                   a["code"].get<std::string>(), a["text"].get<std::string>());
    fmt::print("ncvm check: {} alarm(s), {} warning(s)\n", report["alarms"].size(), report["warnings"].size());
  }
  return report["alarms"].empty() ? kExitOk : kExitAlarm;
}

void printAlarmTable() {
  fmt::print("| code | message | meaning |\n|---|---|---|\n");
  for (const auto& a : alarmTable()) fmt::print("| {} | {} | {} |\n", alarmCode(a.id), a.message, a.meaning);
}

void printCodeTable() {
  static const char* status[] = {"supported", "accepted (no effect on the path)", "alarm PS0010 (not yet)"};
  static const char* series[] = {"M", "T-A", "T-B", "T-C"};
  fmt::print("| G code | series | group | status | meaning |\n|---|---|---|---|---|\n");
  for (const auto& g : gcodeTable()) {
    std::string s;
    for (int k = 0; k < 4; ++k)
      if (g.seriesMask & (1 << k)) s += (s.empty() ? "" : " ") + std::string(series[k]);
    std::string code = fmt::format("G{:02d}", g.code10 / 10);
    if (g.code10 % 10) code += fmt::format(".{}", g.code10 % 10);
    fmt::print("| {} | {} | {} | {} | {} |\n", code, s, g.group == 0 ? std::string("00 (one-shot)") : fmt::format("{:02d}", g.group),
               status[static_cast<int>(g.status)], g.meaning);
  }
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ncvm: a Fanuc-compatible CNC control emulator"};
  app.set_version_flag("--version", "ncvm 0.1.0");
  app.require_subcommand(1);

  CommonOptions runOpts;
  std::string tracePath, statePath, outputPath, machineStatePath;
  bool quiet = false, batch = false;
  unsigned jobs = 0;
  auto* run = app.add_subcommand("run", "run a program and report what the machine does");
  addCommon(run, runOpts);
  run->add_option("--trace", tracePath, "write the event trace (JSON Lines)");
  run->add_option("--state", statePath, "write the final state (JSON)");
  run->add_option("--output", outputPath, "file for DPRNT/BPRNT output");
  run->add_option("--machine-state", machineStatePath,
                  "persistent memory (#500-#999, offsets, part counters): loaded if it exists, saved after the run");
  run->add_flag("-q,--quiet", quiet, "print only alarms");
  run->add_flag("--batch", batch,
                "run every PROGRAM file as a program of its own, in parallel; --trace, --state and --output "
                "then name folders (STEM.jsonl, STEM.json, STEM.txt)");
  run->add_option("-j,--jobs", jobs, "threads for --batch (default: all cores)");

  CommonOptions checkOpts;
  bool json = false;
  auto* check = app.add_subcommand("check", "report what can be found without running");
  addCommon(check, checkOpts);
  check->add_flag("--json", json, "print the findings as JSON");

  app.add_subcommand("alarms", "print the alarm table (Markdown)");
  app.add_subcommand("codes", "print the G-code support table (Markdown)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return kExitUsage;
  }
  try {
    if (run->parsed() && batch)
      return batchCommand(runOpts, tracePath, statePath, outputPath, machineStatePath, quiet, jobs);
    if (run->parsed()) return runCommand(runOpts, tracePath, statePath, outputPath, machineStatePath, quiet);
    if (check->parsed()) return checkCommand(checkOpts, json);
    if (app.got_subcommand("alarms")) printAlarmTable();
    if (app.got_subcommand("codes")) printCodeTable();
    return kExitOk;
  } catch (const SetupError& e) {
    fmt::print(stderr, "ncvm: setup error: {}{}\n", e.what(), e.line ? fmt::format(" (line {})", e.line) : "");
    return kExitUsage;
  } catch (const std::exception& e) {
    fmt::print(stderr, "ncvm: {}\n", e.what());
    return kExitUsage;
  }
}
