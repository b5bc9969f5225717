#pragma once
// One verification job as a library call: load the programs, run or check the main one,
// and build the state and check reports. The CLI, the golden tests and (later) the server
// all go through here.
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "canon/events.hpp"
#include "exec/executor.hpp"
#include "lang/program_store.hpp"
#include "machine/setup.hpp"
#include "timing/time_report.hpp"

namespace ncvm {

class StockModel;

// Where the bundled macros/ folder is: $NCVM_MACROS, beside the executable
// (../share/ncvm/macros), or the source tree this binary was built from.
std::string bundledMacrosFolder();

class Session {
 public:
  explicit Session(Setup setup);

  // The first file's first program is the main program; the others join the store.
  void addProgramFile(const std::string& path);
  // Lets the main program's file be compiled while it runs (ProgramStore::StreamOptions,
  // program_stream.hpp) when it is large and plain enough: set before addProgramFile. Only
  // for run(): check() and the web viewer need the whole program.
  void streamMainProgram(ProgramStore::StreamOptions options) { stream_ = options; }
  void addProgramText(std::string_view text, const std::string& name);
  void addLibrary(const std::string& dir, std::string_view except = {});
  void addBundledMacros();

  const Setup& setup() const { return setup_; }
  SourceFiles& files() { return files_; }
  ProgramStore& store() { return store_; }
  const Program* main() const { return main_; }

  struct Result {
    EndReason end = EndReason::Eof;
    std::optional<Alarm> alarm;
    RunStats stats;
    std::vector<Warning> warnings;
    nlohmann::json state;
    std::string printed;  // DPRNT/BPRNT output
    nlohmann::json machineState;
    nlohmann::json stock;        // the stock model's analysis (null without simulateStock)
    nlohmann::json viewerStock;  // the final stock for the web viewer (keepViewerStock)
    // The cycle-time model's totals and breakdowns (also in state["timing"]); empty when
    // timing is off (setTiming(false)).
    std::shared_ptr<const TimeReport> timing;
  };
  // Simulates the stock ([stock] of the setup, src/sim/stock_model.hpp) beside the run:
  // its files go to outDir (none when empty), its analysis to Result::stock and to
  // state["stock"]. Throws SetupError at run() when the setup cannot be simulated.
  void simulateStock(std::string outDir) {
    stockOn_ = true;
    stockOut_ = std::move(outDir);
  }
  // With simulateStock, also returns the final stock in Result::viewerStock
  // (StockModel::viewerStock: a mill's grid at most maxGrid cells a side).
  void keepViewerStock(int maxGrid) { viewerGrid_ = maxGrid; }
  // With simulateStock, calls `watch(model, moves)` before the stock model takes each move:
  // the model then holds the first `moves` moves of the run (the web viewer's stock along
  // the timeline, server/stock_snapshots.hpp).
  void watchStock(std::function<void(StockModel&, uint64_t)> watch) {
    stockWatch_ = std::move(watch);
  }
  // Runs the main program; `sink` receives every event (may be nullptr). With a
  // machine state (memoryToJson format) the control starts from it instead of the setup's
  // offsets and #500-#999; Result::machineState is what it keeps afterwards.
  Result run(EventSink* sink, const nlohmann::json* machineState = nullptr);

  // Everything found without running: syntax errors, loop and label errors and the
  // decimal-point and duplicate-word warnings, for the programs of the given files.
  nlohmann::json check() const;

  // The cycle-time stage runs by default (setup [timing]); off only for measurements.
  void setTiming(bool on) { timing_ = on; }
  // Lets a sink read the control while it runs (the web viewer's per-step snapshots):
  // called once with the executor before the first block; the executor lives until run()
  // returns.
  void setInspector(std::function<void(Executor&)> f) { inspector_ = std::move(f); }

 private:
  std::function<void(Executor&)> inspector_;
  Setup setup_;
  SourceFiles files_;
  ProgramStore store_;
  const Program* main_ = nullptr;
  std::optional<ProgramStore::StreamOptions> stream_;
  std::vector<const Program*> ownPrograms_;  // from files named on the command line
  std::vector<std::string> ownFiles_;        // their names, for "no program to run"
  bool stockOn_ = false;
  std::string stockOut_;
  int viewerGrid_ = 0;  // 0: no Result::viewerStock
  std::function<void(StockModel&, uint64_t)> stockWatch_;
  bool timing_ = true;
};

nlohmann::json alarmJson(const Alarm& a, const SourceFiles& files);
// The `modal` object of the state report (docs/trace-format.md).
nlohmann::json modalJson(const ModalState& m, const Setup& setup);

}  // namespace ncvm
