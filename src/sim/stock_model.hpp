#pragma once
// The material-removal simulation as the control sees it: an event sink. A stock model only
// ever sees moves (src/canon/events.hpp), never G-code; at the end of the run it writes the
// final stock and its pictures and returns the analysis against the setup's [target].
//
// Two models implement it: the lathe half-profile (sim/lathe_stock.*) and the mill height
// field (sim/mill_stock.*). makeStockModel picks one by the machine kind.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "canon/events.hpp"
#include "machine/setup.hpp"
#include "sim/probe_world.hpp"

namespace ncvm {

class StockModel : public EventSink {
 public:
  // Writes the final stock, the pictures and analysis.json into outDir (created if
  // missing), each file atomically (report/atomic_file.hpp); with an empty outDir it writes
  // nothing. Returns the analysis (docs/stock-analysis.md describes its fields; the
  // "pictures" entries name the files written, relative to outDir). Called once, after
  // the run.
  virtual nlohmann::json finish(const std::string& outDir) = 0;

  // The final stock for the web viewer (docs/web-viewer.md, `stock`): a lathe's profile
  // rings, a mill's height field downsampled to at most maxGrid cells a side
  // (sim/viewer_stock.cpp). Called after finish().
  virtual nlohmann::json viewerStock(int maxGrid) = 0;

  // G31 against the current stock (probe.use_stock): a ProbeWorld in the moves' coordinates
  // (the work system in use, program units, X radial; the model shifts them into its frame,
  // sim/stock_frame.hpp), which sim/stock_probe.hpp places in the machine; it sees every
  // move this sink has received. nullptr when the model cannot be probed.
  virtual const ProbeWorld* probeWorld() const { return nullptr; }
};

// The model for setup.kind, built from setup.stock, setup.target and setup.tools. Throws
// SetupError when the setup has no [stock] or it does not fit the machine kind.
std::unique_ptr<StockModel> makeStockModel(const Setup& setup);

// The two constructors (each in its own file). Both throw SetupError for a bad setup.
std::unique_ptr<StockModel> makeLatheStock(const Setup& setup);
std::unique_ptr<StockModel> makeMillStock(const Setup& setup);

}  // namespace ncvm
