#pragma once
// One verification job: a setup, the programs, then run() or check(). The same engine as the
// ncvm command (a run gives what `ncvm run` gives with the same setup and files).
//
//   ncvm::api::Job job;
//   job.loadPreset("fanuc-0i-mf");           // or loadSetup("my-machine.toml")
//   job.set("DPI=1");                         // a --set override
//   job.addProgramText("G0 X10\nM30\n");     // or addProgramFile("part.nc")
//   ncvm::api::RunResult r = job.run();
//   if (r.alarm) std::cerr << r.alarm->code << ' ' << r.alarm->message << '\n';
//
// Errors of use (a setup key that does not exist, a file that cannot be read, no program)
// throw ncvm::api::Error; alarms of the program are results, never exceptions.
// A Job is used from one thread at a time; separate Jobs may run on separate threads.
#include <memory>
#include <stdexcept>
#include <string>
#include <string_view>

#include "ncvm/events.hpp"
#include "ncvm/export.hpp"
#include "ncvm/result.hpp"

namespace ncvm::api {

// A setup error names FILE:LINE:COL: KEY: WHY like `ncvm run` does.
class NCVM_API Error : public std::runtime_error {
 public:
  explicit Error(const std::string& what);
  ~Error() override;
};

class NCVM_API Job {
 public:
  Job();  // ncvm's default setup: a 3-axis mill, Fanuc 0i-F
  ~Job();
  Job(Job&&) noexcept;
  Job& operator=(Job&&) noexcept;
  Job(const Job&) = delete;
  Job& operator=(const Job&) = delete;

  // Setup, in the order given (later ones override, as repeated --setup and --set do).
  void loadSetup(const std::string& path);   // TOML, docs/setup-format.md
  void loadPreset(const std::string& name);  // a bundled preset: presets/NAME.toml
  void set(const std::string& keyValue);     // "3401#0=1", "DPI=1", "machine.kind=lathe"

  // Programs. The first program of the first file (or text) given is the one that runs; the
  // others, folders and the bundled macros/ folder are there for M98/G65 calls.
  void addProgramText(std::string_view text, const std::string& name = "<text>");
  void addProgramFile(const std::string& path);
  void addFolder(const std::string& path);  // every program file in it (as --lib)
  void useBundledMacros(bool on);           // on by default (as without --no-macros)

  // Runs the main program; `events` (may be null) receives each event as it happens.
  RunResult run(EventHandler* events = nullptr);
  // What can be found without running (as `ncvm check`).
  CheckResult check();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// Where the bundled data of this library were found (macros/, presets/): the folder that
// holds them, or empty. Installed: PREFIX/share/ncvm.
NCVM_API std::string dataFolder();

}  // namespace ncvm::api
