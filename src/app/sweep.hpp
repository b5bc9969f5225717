#pragma once
// Parameter studies (`ncvm sweep`): one program run over every combination of a few setup
// values (any --set key: offsets, tools, parameters, vars.#n), each run with the stock
// simulation, the analyses tabulated. Seed 002's face-milling question (which D and which
// cutter leave nothing uncut) is one command.
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "machine/setup.hpp"

namespace ncvm {

struct SweepAxis {
  std::string key;                  // a --set key
  std::vector<std::string> values;  // as --set values
};

// "KEY=FROM:TO:STEP" (inclusive) or "KEY=V1,V2,...". Throws SetupError when malformed.
SweepAxis parseSweepAxis(const std::string& spec);

struct SweepRow {
  std::vector<std::string> values;  // one per axis
  std::string end;                  // how the run ended, or "setup error"
  std::string alarm;                // code and text, empty if none
  nlohmann::json stock;             // the stock analysis (null without [stock] or on error)
  std::string dir;                  // its files, when written
};

// Runs every combination (the first axis varies slowest). `run(setup, outDir)` runs the
// program and returns {end, alarm, stock}; outDir is empty unless `outRoot` is given, then
// outRoot/<key=value_...>.
std::vector<SweepRow> runSweep(
    const Setup& base, const std::vector<SweepAxis>& axes, const std::string& outRoot,
    const std::function<SweepRow(const Setup&, const std::string&)>& run);

// The table: a Markdown table with one row per run, and the combinations that leave nothing
// uncut (no alarm, a target, uncut area 0, no collision).
std::string sweepMarkdown(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows);
std::string sweepCsv(const std::vector<SweepAxis>& axes, const std::vector<SweepRow>& rows);
bool sweepRowClean(const SweepRow& r);

}  // namespace ncvm
