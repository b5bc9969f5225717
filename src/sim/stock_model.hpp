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
#include <vector>

#include "canon/events.hpp"
#include "machine/setup.hpp"
#include "sim/probe_world.hpp"

namespace ncvm {

// The stock as the web viewer draws it, in numbers (sim/viewer_stock.cpp): a mill's height
// field shrunk to a grid, or a lathe's half-profile rings. The JSON of viewerStock() and the
// binary snapshots of the timeline (server/stock_snapshots.hpp) are both made from it.
struct ViewerStockData {
  bool grid = false;  // true: a mill's grid; false: a lathe's rings
  // The grid: nx * ny heights, row by row from y0, each row from x0; each the lowest of its
  // step x step block of field cells. x1, y1 are the field's far edges.
  int nx = 0, ny = 0, step = 1;
  double x0 = 0, y0 = 0, x1 = 0, y1 = 0, cell = 0, top = 0, bottom = 0;
  std::vector<float> z;
  // The rings: points [z, x, z, x, ...] (X a diameter, as profile.csv), and whether each is
  // a hole.
  struct Ring {
    bool hole = false;
    std::vector<double> zx;
  };
  std::vector<Ring> rings;
};

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

  // The stock as cut by the moves received so far, in the same form, taken during the run
  // (the viewer's timeline, server/stock_snapshots.hpp). Taking it does not change how later
  // moves are cut: the final stock is the same with snapshots or without, and the snapshot
  // after k moves is the final stock of a run of those k moves alone.
  virtual ViewerStockData viewerSnapshot(int maxGrid) = 0;

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
