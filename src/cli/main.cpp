// The ncvm command: run, check, compare, sweep, serve (the web viewer), and the generated
// reference tables (alarms, codes).
// Exit status: 0 normal end, 3 alarm, 2 usage or setup error.
#include <fmt/format.h>
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <set>
#include <thread>

#include "app/compare.hpp"
#include "app/machine_state.hpp"
#include "app/machine_state_file.hpp"
#include "app/session.hpp"
#include "app/sweep.hpp"
#include "cli/command_line.hpp"
#include "cli/serve_options.hpp"
#include "cli/terminal.hpp"
#include "core/alarm.hpp"
#include "core/edit_distance.hpp"
#include "core/program_files.hpp"
#include "core/version.hpp"
#include "exec/gcode_table.hpp"
#include "lsp/stdio_server.hpp"
#include "report/atomic_file.hpp"
#include "report/clock_time.hpp"
#include "report/html_report.hpp"
#include "report/output_folder.hpp"
#include "report/report_recorder.hpp"
#include "report/temp_cleanup.hpp"
#include "report/trace_writer.hpp"
#include "server/worker.hpp"
#include "sim/deviation.hpp"

namespace {

using namespace ncvm;

constexpr int kExitOk = 0;
constexpr int kExitUsage = 2;
constexpr int kExitAlarm = 3;

struct CommonOptions {
  std::vector<std::string> programs;
  std::vector<std::string> setupPaths;
  std::vector<std::string> libs;
  std::vector<std::string> sets;
  bool noMacros = false;
  // run only: the main program's file compiled while it runs (program_stream.hpp)
  ProgramStore::StreamOptions stream;
};

void addSetupOptions(CLI::App* cmd, CommonOptions& o);

void addCommon(CLI::App* cmd, CommonOptions& o) {
  cmd->add_option("PROGRAM", o.programs,
                  "program file(s), - for standard input; the first file's first program runs")
      ->required();
  addSetupOptions(cmd, o);
}

void addSetupOptions(CLI::App* cmd, CommonOptions& o) {
  cmd->add_option("--setup", o.setupPaths,
                  "machine and job setup (TOML, docs/setup-format.md), or a bundled preset's name "
                  "(fanuc-0i-mf); repeatable: later files override, e.g. a preset then the job");
  cmd->add_option("--lib", o.libs, "folder of programs for M98/G65 calls (repeatable)");
  cmd->add_option("--set", o.sets,
                  "override a setting: 3401#0=1, DPI=1, block_skip.1=true, limits.max_blocks=1000");
  cmd->add_flag("--no-macros", o.noMacros, "do not load the bundled macros/ folder");
}

// --setup NAME that names no file and has no folder part: the bundled preset NAME(.toml),
// from the presets/ folder beside the bundled macros (PREFIX/share/ncvm/presets installed).
std::string setupFile(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(path, ec) || path.find('/') != std::string::npos) return path;
  const std::string macros = bundledMacrosFolder();
  if (macros.empty()) return path;
  fs::path preset = fs::path(macros).parent_path() / "presets" / path;
  if (preset.extension() != ".toml") preset += ".toml";
  return fs::is_regular_file(preset, ec) ? preset.string() : path;
}

Setup makeSetup(const CommonOptions& o) {
  Setup s = defaultSetup();
  for (const auto& path : o.setupPaths) loadSetupInto(s, setupFile(path));
  for (const auto& kv : o.sets) applySetting(s, kv);
  return s;
}

// `-` as a program is standard input (an editor pipes the buffer in), read whole, within
// limits.max_file_bytes; alarms name it <stdin>.
std::string readStandardInput(uint64_t maxBytes) {
  std::string text;
  char buf[1 << 16];
  size_t got = 0;
  while ((got = std::fread(buf, 1, sizeof buf, stdin)) > 0) {
    text.append(buf, got);
    if (text.size() > maxBytes)
      throw std::runtime_error(
          fmt::format("standard input: larger than limits.max_file_bytes = {}", maxBytes));
  }
  if (std::ferror(stdin))
    throw std::runtime_error(fmt::format("standard input: cannot read: {}", std::strerror(errno)));
  return text;
}

void loadPrograms(Session& session, const CommonOptions& o) {
  if (std::count(o.programs.begin(), o.programs.end(), "-") > 1)
    throw std::runtime_error("standard input (-) can be only one of the programs");
  for (const auto& p : o.programs)
    if (p == "-")
      session.addProgramText(readStandardInput(session.setup().limits.maxFileBytes), "<stdin>");
    else
      session.addProgramFile(p);
  for (const auto& l : o.libs) session.addLibrary(l);
  if (!o.noMacros) session.addBundledMacros();
}

// Program text may hold bytes that are not UTF-8 (comments, names): the reports replace
// them with U+FFFD instead of failing.
std::string dumpJson(const nlohmann::json& j) {
  return j.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

// Text from the program (a message, a comment, a file name) for the terminal: control bytes
// as \xNN, so a program cannot move the cursor or clear the screen of whoever runs it.
std::string printable(std::string_view text) {
  std::string out;
  for (unsigned char c : text) {
    if (c < 0x20 || c == 0x7f)
      out += fmt::format("\\x{:02X}", c);
    else
      out += static_cast<char>(c);
  }
  return out;
}

std::string alarmLine(const Alarm& a, const SourceFiles& files) {
  std::string s = fmt::format("{}:{}:{}: {} {}", printable(files.name(a.loc.file)), a.loc.line,
                              a.loc.col, a.code, printable(a.text));
  if (a.n) s += fmt::format(" (N{})", *a.n);
  return s;
}

struct RunOutputs {
  std::string trace, state, output, machineState, stockOut, report;
  double lockWait = 60;  // seconds a run waits for another holding the machine state
};

// One run; what it would print goes to `out` (stdout) and `err` (stderr), so batch runs on
// several threads can print each program's report whole, in command-line order.
// `progress`: a progress line on standard error when it is a terminal (not for batch runs,
// whose programs run side by side).
int runOne(const CommonOptions& o, const RunOutputs& outs, bool quiet, std::string& out,
           std::string& err, bool progress = false) {
  auto outAt = std::back_inserter(out);
  auto errAt = std::back_inserter(err);
  const std::string& tracePath = outs.trace;
  const std::string& statePath = outs.state;
  const std::string& outputPath = outs.output;
  const std::string& machineStatePath = outs.machineState;
  // One output may go to standard output (-); the summary then goes to standard error.
  const int toStdout = isStdoutPath(tracePath) + isStdoutPath(statePath) +
                       isStdoutPath(outputPath) + isStdoutPath(outs.report);
  if (toStdout > 1)
    throw std::runtime_error(
        "only one of --trace, --state, --output and --report can be - (standard output)");
  Session session(makeSetup(o));
  session.streamMainProgram(o.stream);
  loadPrograms(session, o);
  // --stock-out is written as a set: into a temporary folder beside it, put in place after
  // the run (output_folder.hpp). The report inlines the stock pictures: without --stock-out
  // they are made in a private temporary folder that is removed afterwards.
  std::string stockDir;
  std::optional<OutputFolder> stockSet;
  bool tempStock = false;
  // --stock-out without [stock]: nothing to simulate, said once; the run and its other
  // outputs (the report says so too) go on.
  const bool noStock = !outs.stockOut.empty() && !session.setup().stock.present;
  if (noStock)
    fmt::format_to(errAt,
                   "ncvm: warning: --stock-out {}: no stock in the setup (no [stock] section): "
                   "nothing written there\n",
                   outs.stockOut);
  if (!outs.stockOut.empty() && !noStock) {
    try {
      stockSet.emplace(outs.stockOut);
    } catch (const std::runtime_error& e) {
      throw std::runtime_error(fmt::format("--stock-out {}", e.what()));  // which option's folder
    }
    stockDir = stockSet->temporary();
  } else if (!outs.report.empty() && outs.stockOut.empty() && session.setup().stock.present) {
    std::string pattern = (std::filesystem::temp_directory_path() / "ncvm-report-XXXXXX").string();
    if (!::mkdtemp(pattern.data()))
      throw std::runtime_error(
          fmt::format("cannot create a temporary folder: {}", std::strerror(errno)));
    stockDir = pattern;
    tempStock = true;
  }
  if (!stockDir.empty()) session.simulateStock(stockDir);
  const std::string warningWord =
      cli::painted("warning:", cli::Paint::Yellow, cli::colourWanted(stderr));
  for (const auto& w : session.store().warnings())
    fmt::format_to(errAt, "ncvm: {} {}\n", warningWord, w);

  std::unique_ptr<AtomicFile> traceFile;
  std::unique_ptr<TraceWriter> trace;
  if (!tracePath.empty()) {
    traceFile = std::make_unique<AtomicFile>(tracePath);
    trace = std::make_unique<TraceWriter>(session.files(), traceFile->get(),
                                          session.setup().limits.maxTraceBytes,
                                          session.setup().reportedAxes());
  }
  // Locked from before the read until after the write: runs sharing it take turns.
  std::optional<MachineStateFile> machineState;
  if (!machineStatePath.empty()) machineState.emplace(machineStatePath, outs.lockWait);
  const nlohmann::json* memory = machineState ? machineState->load(session.setup()) : nullptr;
  // The report's tool path, G31 moves and offset writes, recorded beside the trace.
  std::unique_ptr<ReportRecorder> recorder;
  FanoutSink sinks;
  EventSink* sink = trace.get();
  if (!outs.report.empty()) {
    recorder = std::make_unique<ReportRecorder>(session.setup());
    if (trace) sinks.add(trace.get());
    sinks.add(recorder.get());
    sink = &sinks;
  }
  cli::MoveCounter counter;
  std::optional<cli::ProgressLine> progressLine;
  FanoutSink counted;
  if (progress && !quiet && cli::isTerminal(stderr)) {
    counted.add(&counter);
    if (sink) counted.add(sink);
    sink = &counted;
    progressLine.emplace(session.files().name(session.main()->loc.file), counter);
  }
  Session::Result r = session.run(sink, memory);
  progressLine.reset();  // erases the line before anything else is printed
  // Every output is attempted even when one fails (a full disk): the machine state first,
  // then the others; each failure is reported with its own file, and the run exits 2.
  std::vector<std::string> failed;
  auto attempt = [&failed](auto&& write) {
    try {
      write();
    } catch (const std::runtime_error& e) {
      failed.emplace_back(e.what());
    }
  };
  // The control keeps its memory whatever way the run ended, alarms included.
  if (machineState) attempt([&] { machineState->save(dumpJson(r.machineState) + "\n"); });
  machineState.reset();
  if (trace) {
    attempt([&] {
      try {
        trace->flush();
      } catch (const AlarmError&) {  // a write failed: its reason is writeError()
      }
      if (int why = trace->writeError())
        throw std::runtime_error(
            fmt::format("{}: cannot write the trace: {}", tracePath, std::strerror(why)));
      trace.reset();
      traceFile->commit();
    });
    trace.reset();
    traceFile.reset();
  }
  if (stockSet) {
    attempt([&] {
      stockSet->commit();
      stockDir = outs.stockOut;  // the report inlines the pictures from their place
    });
  }
  if (!statePath.empty()) attempt([&] { writeFileAtomic(statePath, dumpJson(r.state) + "\n"); });
  if (!outs.report.empty()) {
    const Program* m = session.main();
    attempt([&] {
      const std::string title =
          fmt::format("ncvm: {} ({})", session.files().name(m->loc.file), m->label);
      ReportInputs in;
      in.recorder = recorder.get();
      in.setup = &session.setup();
      in.files = &session.files();
      writeFileAtomic(outs.report, htmlReport(r.state, title, stockDir, in));
    });
  }
  if (tempStock) std::filesystem::remove_all(stockDir);
  std::string dprnt = !outputPath.empty() ? outputPath : session.setup().dprntPath;
  if (!r.printed.empty()) {
    if (dprnt.empty())
      err += "ncvm: warning: DPRNT output discarded (give --output FILE or output.dprnt)\n";
    else
      attempt([&] { writeFileAtomic(dprnt, r.printed); });
  }

  const Program* main = session.main();
  // The summary's colours, only when it goes to a terminal (stderr when stdout carries data).
  const bool colourOut = cli::colourWanted(toStdout ? stderr : stdout);
  if (!quiet) {
    fmt::format_to(outAt, "ncvm: {} ({}) ended: {}\n", session.files().name(main->loc.file),
                   main->label,
                   cli::painted(endReasonName(r.end), r.alarm ? cli::Paint::Red : cli::Paint::Green,
                                colourOut));
    std::string cycle = fmt::format("{} (length/feed)", clockTime(r.stats.time));
    if (session.setup().timing.dynamic && r.timing)
      cycle = fmt::format("{} (modelled), {} (length/feed)", clockTime(r.timing->total().model),
                          clockTime(r.stats.time));
    fmt::format_to(
        outAt, "  blocks {}, moves {}, path {:.3f} (rapid {:.3f}, feed {:.3f}), cycle time {}\n",
        r.stats.blocks, r.stats.moves, r.stats.rapidLength + r.stats.feedLength,
        r.stats.rapidLength, r.stats.feedLength, cycle);
    for (const auto& w : r.warnings)
      fmt::format_to(outAt, "{}:{}:{}: {} {}\n", session.files().name(w.loc.file), w.loc.line,
                     w.loc.col, cli::painted(w.code, cli::Paint::Yellow, colourOut), w.text);
    if (!tracePath.empty()) fmt::format_to(outAt, "  trace: {}\n", tracePath);
    if (!statePath.empty()) fmt::format_to(outAt, "  state: {}\n", statePath);
    if (r.stock.is_object()) {
      const auto& st = r.stock;
      if (st.contains("deviation") && !notMeasuredText(st["deviation"]).empty())
        fmt::format_to(outAt, "  stock: deviation {}\n", notMeasuredText(st["deviation"]));
      else if (st.contains("deviation") && st["deviation"].is_object())
        fmt::format_to(
            outAt,
            "  stock: deviation max {:.4f} (excess {:.4f}, gouge {:.4f}), mean {:.4f}, {:.1f} % "
            "within {}\n",
            st["deviation"]["max"].get<double>(), st["deviation"]["max_excess"].get<double>(),
            st["deviation"]["max_gouge"].get<double>(), st["deviation"]["mean"].get<double>(),
            100 * st["deviation"]["in_tolerance"].get<double>(),
            st["deviation"]["tolerance"].get<double>());
      if (st.contains("collisions") && !st["collisions"].empty())
        fmt::format_to(outAt, "  stock: {} collision(s), the first at {}:{}\n",
                       st["collisions"].size(), st["collisions"][0].value("file", std::string()),
                       st["collisions"][0].value("line", 0));
      if (!outs.stockOut.empty()) fmt::format_to(outAt, "  stock: {}\n", outs.stockOut);
    }
    if (!outs.report.empty()) fmt::format_to(outAt, "  report: {}\n", outs.report);
    if (!r.printed.empty() && !dprnt.empty()) fmt::format_to(outAt, "  output: {}\n", dprnt);
  }
  if (r.alarm)
    fmt::format_to(outAt, "{}\n",
                   cli::painted(alarmLine(*r.alarm, session.files()), cli::Paint::Red, colourOut));
  if (toStdout) {
    err += out;
    out.clear();
  }
  for (const auto& f : failed) fmt::format_to(errAt, "ncvm: {}\n", f);
  if (!failed.empty()) return kExitUsage;
  return r.alarm ? kExitAlarm : kExitOk;
}

// Runs two programs on the same setup and prints them side by side. Exit status as for
// run: 3 when either ends in an alarm (its alarm line is printed), 2 on a usage error.
int compareCommand(const CommonOptions& o, const std::string& a, const std::string& b, bool json) {
  Setup setup = makeSetup(o);
  auto runProgram = [&](const std::string& file, std::string& alarmText) {
    Session session(setup);
    CommonOptions one = o;
    one.programs = {file};
    loadPrograms(session, one);
    for (const auto& w : session.store().warnings()) fmt::print(stderr, "ncvm: warning: {}\n", w);
    ComparedRun run{file, session.run(nullptr)};
    if (run.result.alarm) alarmText = alarmLine(*run.result.alarm, session.files());
    return run;
  };
  std::string alarmA, alarmB;
  ComparedRun ra = runProgram(a, alarmA);
  ComparedRun rb = runProgram(b, alarmB);
  if (json)
    fmt::print("{}\n", dumpJson(compareJson(ra, rb, setup.timing.dynamic)));
  else
    fmt::print("{}", compareText(ra, rb, setup.timing.dynamic));
  for (const auto* line : {&alarmA, &alarmB})
    if (!line->empty()) fmt::print("{}\n", *line);
  return alarmA.empty() && alarmB.empty() ? kExitOk : kExitAlarm;
}

int runCommand(const CommonOptions& o, const RunOutputs& outs, bool quiet) {
  std::string out, err;
  int rc = 0;
  try {
    rc = runOne(o, outs, quiet, out, err, true);
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
int batchCommand(const CommonOptions& o, const RunOutputs& dirs, bool quiet, unsigned jobs) {
  const std::string& traceDir = dirs.trace;
  const std::string& stateDir = dirs.state;
  const std::string& outputDir = dirs.output;
  if (!dirs.stockOut.empty() || !dirs.report.empty())
    throw std::runtime_error("--stock-out and --report are for one program, not a batch");
  if (!dirs.machineState.empty())
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
        RunOutputs files;
        files.trace = in(traceDir, stems[k], ".jsonl");
        files.state = in(stateDir, stems[k], ".json");
        files.output = in(outputDir, stems[k], ".txt");
        codes[k] = runOne(one, files, quiet, outs[k], errs[k]);
      } catch (const SetupError& e) {
        errs[k] += fmt::format("ncvm: setup error: {}\n", setupErrorText(e));
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
  // What loading found (a duplicate program, text after the closing '%'), as run prints it.
  for (const auto& w : session.store().warnings()) fmt::print(stderr, "ncvm: warning: {}\n", w);
  nlohmann::json report = session.check();
  if (json) {
    fmt::print("{}\n", dumpJson(report));
  } else {
    const bool colour = cli::colourWanted(stdout);
    for (const char* kind : {"alarms", "warnings"})
      for (const auto& a : report[kind])
        fmt::print("{}:{}:{}: {} {}\n", printable(a["file"].get<std::string>()),
                   a["line"].get<int>(), a["col"].get<int>(),
                   cli::painted(a["code"].get<std::string>(),
                                kind[0] == 'a' ? cli::Paint::Red : cli::Paint::Yellow, colour),
                   printable(a["text"].get<std::string>()));
    fmt::print("ncvm check: {} alarm(s), {} warning(s)\n", report["alarms"].size(),
               report["warnings"].size());
  }
  return report["alarms"].empty() ? kExitOk : kExitAlarm;
}

// `ncvm lsp`: the language server on standard input and output (docs/editors.md). The setup
// is read once, so a bad one is a setup error before the editor connects.
int lspCommand(const CommonOptions& o, uint64_t dryRunBlocks) {
  // A --lib folder that is not there is a usage error now, not a silent gap in every lookup.
  for (const auto& dir : o.libs)
    if (std::error_code ec; !std::filesystem::is_directory(dir, ec))
      throw std::runtime_error(fmt::format("--lib {}: not a folder", dir));
  lsp::ServerOptions options;
  options.libs = o.libs;
  options.setupPaths = o.setupPaths;
  options.sets = o.sets;
  options.noMacros = o.noMacros;
  options.dryRunBlocks = dryRunBlocks;
  return lsp::runStdioServer(0, 1, makeSetup(o), std::move(options));
}

// ncvm sweep: the program over every combination of --vary values, with the stock analysis.
int sweepCommand(const CommonOptions& o, const std::vector<std::string>& varies,
                 const std::string& outRoot, bool csv) {
  std::vector<SweepAxis> axes;
  for (const auto& v : varies) axes.push_back(parseSweepAxis(v));
  Setup base = makeSetup(o);
  if (!base.stock.present)
    throw SetupError("sweep tabulates the stock analysis: the setup needs a [stock] section",
                     "stock");
  auto rows = runSweep(base, axes, outRoot, [&](const Setup& s, const std::string& dir) {
    Session session(s);
    loadPrograms(session, o);
    session.simulateStock(dir);
    Session::Result r = session.run(nullptr);
    SweepRow row;
    row.end = endReasonName(r.end);
    if (r.alarm) row.alarm = fmt::format("{} {}", r.alarm->code, r.alarm->text);
    row.stock = r.stock;
    return row;
  });
  std::string table = csv ? sweepCsv(axes, rows) : sweepMarkdown(axes, rows);
  if (!outRoot.empty()) writeFileAtomic(outRoot + (csv ? "/sweep.csv" : "/sweep.md"), table);
  fmt::print("{}", table);
  return kExitOk;
}

// `ncvm list DIR...`: every program file under the folders and the setup it runs with
// (core/program_files.hpp), one "PROGRAM<TAB>SETUP" line each ("-": the default machine).
// `make demo` runs what this lists, so the demo, `ncvm serve` and the docs share one rule.
int listCommand(const std::vector<std::string>& dirs) {
  constexpr int kListDepth = 6;
  for (const auto& dir : dirs)
    for (const auto& prog : programFilesUnder(dir, kListDepth)) {
      const auto setup = setupFileFor(prog);
      fmt::print("{}\t{}\n", prog.string(), setup.empty() ? std::string("-") : setup.string());
    }
  return kExitOk;
}

void printAlarmTable() {
  fmt::print("| code | message | meaning |\n|---|---|---|\n");
  for (const auto& a : alarmTable())
    fmt::print("| {} | {} | {} |\n", alarmCode(a.id), a.message, a.meaning);
}

void printCodeTable() {
  static const char* status[] = {"supported", "accepted (no effect on the path)",
                                 "alarm PS0010 (not yet)"};
  static const char* series[] = {"M", "T-A", "T-B", "T-C"};
  fmt::print("| G code | series | group | status | meaning |\n|---|---|---|---|---|\n");
  for (const auto& g : gcodeTable()) {
    std::string s;
    for (int k = 0; k < 4; ++k)
      if (g.seriesMask & (1 << k)) s += (s.empty() ? "" : " ") + std::string(series[k]);
    std::string code = fmt::format("G{:02d}", g.code10 / 10);
    if (g.code10 % 10) code += fmt::format(".{}", g.code10 % 10);
    fmt::print("| {} | {} | {} | {} | {} |\n", code, s,
               g.group == 0 ? std::string("00 (one-shot)") : fmt::format("{:02d}", g.group),
               status[static_cast<int>(g.status)], g.meaning);
  }
}

// `ncvm serve` runs ncvm-serve beside this binary with the same arguments: the web server
// and its HTTP library (with OpenSSL and brotli) live there, so that every other command
// starts without loading them (about 5 ms of CPU a start, docs/performance.md).
int startServer(int argc, char** argv) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (ec) throw std::runtime_error("cannot find the ncvm binary");
  const std::string server = (exe.parent_path() / "ncvm-serve").string();
  std::vector<char*> args;
  args.push_back(const_cast<char*>(server.c_str()));
  int first = 1;
  while (first < argc && std::string_view(argv[first]) != "serve") ++first;
  for (int k = first + 1; k < argc; ++k) args.push_back(argv[k]);  // what follows "serve"
  args.push_back(nullptr);
  std::fflush(stdout);
  ::execv(server.c_str(), args.data());
  throw std::runtime_error(fmt::format("cannot start {}: {}", server, std::strerror(errno)));
}

// `ncvm rnu x.nc`: CLI11 would say "A subcommand is required"; say which word is not a
// command and the nearest one that is.
std::optional<int> unknownCommand(CLI::App& app, int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') return std::nullopt;
  const std::string_view word = argv[1];
  std::string best, all;
  size_t bestDistance = 3;
  for (const CLI::App* sc : app.get_subcommands([](CLI::App*) { return true; })) {
    if (sc->get_name() == word) return std::nullopt;
    if (sc->get_group().empty()) continue;  // internal (serve-worker)
    all += (all.empty() ? "" : ", ") + sc->get_name();
    if (size_t d = editDistance(word, sc->get_name()); d < bestDistance) {
      bestDistance = d;
      best = sc->get_name();
    }
  }
  fmt::print(stderr, "ncvm: unknown command {}{}\nncvm: the commands are {} (ncvm --help)\n",
             printable(word), best.empty() ? "" : fmt::format(" (did you mean {}?)", best), all);
  return kExitUsage;
}

// --help: FILE, DIR and KEY=VALUE instead of CLI11's TEXT, and the exit codes with an example.
void describeValues(CLI::App& app) {
  static const std::set<std::string> files = {"PROGRAM",  "A",        "B",
                                              "--setup",  "--trace",  "--state",
                                              "--output", "--report", "--machine-state"};
  static const std::set<std::string> dirs = {"--lib", "--stock-out", "--out", "--root", "DIR"};
  static const std::set<std::string> settings = {"--set", "--vary"};
  for (CLI::App* sc : app.get_subcommands([](CLI::App*) { return true; }))
    for (CLI::Option* opt : sc->get_options()) {
      const std::string name = opt->get_name();
      if (files.count(name))
        opt->type_name("FILE");
      else if (dirs.count(name))
        opt->type_name("DIR");
      else if (settings.count(name))
        opt->type_name("KEY=VALUE");
    }
  const std::string footer =
      "\nExit status: 0 the program ended normally (M02/M30 or its end), 3 it ended in an alarm,\n"
      "2 a usage or setup error (bad option, unreadable file, bad setup).\n\n"
      "Example:\n  ncvm run examples/macro-basics/bolt-circle.nc --trace t.jsonl --state s.json\n"
      "  ncvm run prog.nc --setup presets/fanuc-0i-mf.toml --set DPI=1\n";
  app.footer(footer);
  for (CLI::App* sc : app.get_subcommands([](CLI::App*) { return true; })) sc->footer(footer);
}

}  // namespace

int main(int argc, char** argv) {
  installTempCleanup();
  CLI::App app{"ncvm: a Fanuc-compatible CNC control emulator"};
  app.set_version_flag("--version", std::string("ncvm ") + versionText());
  app.require_subcommand(1);

  CommonOptions runOpts;
  RunOutputs outs;
  bool quiet = false, batch = false;
  unsigned jobs = 0;
  auto* run = app.add_subcommand("run", "run a program and report what the machine does");
  addCommon(run, runOpts);
  run->add_option("--trace", outs.trace,
                  "write the event trace (JSON Lines); - for standard output");
  run->add_option("--state", outs.state, "write the final state (JSON); - for standard output");
  run->add_option("--output", outs.output, "file for DPRNT/BPRNT output");
  run->add_option(
      "--stock-out", outs.stockOut,
      "simulate the setup's [stock]: write the final stock, pictures and analysis.json into DIR");
  run->add_option("--report", outs.report,
                  "write a self-contained HTML report (summary, alarms, pictures, deviation)");
  run->add_option("--machine-state", outs.machineState,
                  "persistent memory (#500-#999, offsets, part counters): loaded if it exists, "
                  "saved after the run");
  run->add_option("--lock-wait", outs.lockWait,
                  "seconds to wait while another run holds the --machine-state file (default 60)")
      ->check(CLI::Range(0.0, 86400.0));
  run->add_flag("-q,--quiet", quiet, "print only alarms");
  run->add_flag(
      "--batch", batch,
      "run every PROGRAM file as a program of its own, in parallel; --trace, --state and --output "
      "then name folders (STEM.jsonl, STEM.json, STEM.txt)");
  run->add_option("-j,--jobs", jobs, "threads for --batch (default: all cores)");
  run->add_option(
      "--stream-min-bytes", runOpts.stream.minBytes,
      "compile a main program file of at least this size while it runs, a piece at a time, "
      "when it has no macro statements (default 4194304; docs/performance.md)");
  run->add_option("--stream-piece-bytes", runOpts.stream.pieceBytes,
                  "size of those pieces (default 65536)")
      ->check(CLI::Range(size_t{1}, size_t{1} << 30));

  CommonOptions checkOpts;
  bool json = false;
  auto* check = app.add_subcommand("check", "report what can be found without running");
  addCommon(check, checkOpts);
  check->add_flag("--json", json, "print the findings as JSON");

  CommonOptions sweepOpts;
  std::vector<std::string> varies;
  std::string sweepOut;
  bool sweepCsvOut = false;
  auto* sweep = app.add_subcommand(
      "sweep", "run one program over a range of setup values and tabulate the stock analysis");
  addCommon(sweep, sweepOpts);
  sweep
      ->add_option("--vary", varies,
                   "KEY=FROM:TO:STEP or KEY=V1,V2,... (any --set key, e.g. "
                   "tool_offsets.52.d_geometry=10:30:5, tools.1.diameter=50,63,80, "
                   "vars.#500=1,2); repeatable: every combination runs")
      ->required();
  sweep->add_option("--out", sweepOut,
                    "write each run's stock files into DIR/KEY=VALUE_... and the table into DIR");
  sweep->add_flag("--csv", sweepCsvOut, "print CSV instead of a Markdown table");
  CommonOptions compareOpts;
  std::string programA, programB;
  bool compareJsonOut = false;
  auto* compare =
      app.add_subcommand("compare", "run two programs on the same setup and compare their times");
  compare->add_option("A", programA, "first program file")->required();
  compare->add_option("B", programB, "second program file")->required();
  addSetupOptions(compare, compareOpts);
  compare->add_flag("--json", compareJsonOut, "print the comparison as JSON");
  ServeOptions serveOpts;
  auto* serve = app.add_subcommand("serve", kServeDescription);
  addServeOptions(serve, serveOpts);
  uint64_t workerMemory = 0;
  auto* worker = app.add_subcommand("serve-worker", "");  // internal: one run for `ncvm serve`
  worker->group("");
  worker->add_option("--memory", workerMemory);

  std::vector<std::string> listDirs;
  auto* list = app.add_subcommand(
      "list",
      "list the program files under DIR and the setup each one runs with (as make demo runs them)");
  list->add_option("DIR", listDirs, "folder(s) to list")
      ->required()
      ->check(CLI::ExistingDirectory)
      ->type_name("DIR");
  CommonOptions lspOpts;
  uint64_t lspBlocks = lsp::ServerOptions{}.dryRunBlocks;
  auto* lspCmd = app.add_subcommand(
      "lsp", "language server for editors on standard input/output (LSP, docs/editors.md)");
  addSetupOptions(lspCmd, lspOpts);
  lspCmd
      ->add_option("--max-blocks", lspBlocks,
                   "blocks the dry run of a document may execute before it stops (default "
                   "200000; the setup's limits.max_blocks when smaller)")
      ->check(CLI::Range(uint64_t{1}, uint64_t{1} << 40))
      ->type_name("N");
  app.add_subcommand("alarms", "print the alarm table (Markdown)");
  app.add_subcommand("codes", "print the G-code support table (Markdown)");

  describeValues(app);
  if (const auto status = unknownCommand(app, argc, argv)) return *status;
  if (const auto status = parseCommandLine(app, argc, argv)) return *status;
  try {
    if (run->parsed() && batch) return batchCommand(runOpts, outs, quiet, jobs);
    if (run->parsed()) return runCommand(runOpts, outs, quiet);
    if (check->parsed()) return checkCommand(checkOpts, json);
    if (sweep->parsed()) return sweepCommand(sweepOpts, varies, sweepOut, sweepCsvOut);
    if (compare->parsed()) return compareCommand(compareOpts, programA, programB, compareJsonOut);
    if (serve->parsed()) return startServer(argc, argv);
    if (worker->parsed()) return server::workerMain(workerMemory);
    if (list->parsed()) return listCommand(listDirs);
    if (lspCmd->parsed()) return lspCommand(lspOpts, lspBlocks);
    if (app.got_subcommand("alarms")) printAlarmTable();
    if (app.got_subcommand("codes")) printCodeTable();
    return kExitOk;
  } catch (const std::exception& e) {
    return commandError(e);
  }
}
