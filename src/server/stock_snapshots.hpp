#pragma once
// The stock along the viewer's timeline: snapshots of the stock simulation taken while the
// program runs, every `every` moves, at most `keep` of them. When a run makes more, every
// other one is dropped and the interval doubles (moves 0, N, 2N, ... become 0, 2N, 4N, ...),
// so a 100,000-move program ends with fewer than `keep` snapshots spread over the whole run
// however long it turns out to be, and a short one has the stock after every move.
//
// Each snapshot is exact: it is the stock the simulation holds after its first k moves, the
// final stock of a run of those moves alone (StockModel::viewerSnapshot). The final stock of
// the run is sent apart, in the end frame (answer.stock).
//
// A snapshot is the payload of a kind 6 frame (viewer_stream.hpp), little-endian:
//   u32[8]  k (low, high 32 bits), type (0 grid, 1 profile), then for a grid nx, ny, step,
//           0, 0; for a profile the ring count, 0, 0, 0
//   grid:    f64[7] x0, y0, x1, y1, cell, top, bottom; f32[nx * ny] the heights, row by row
//            from y0, each row from x0 (as answer.stock's "z")
//   profile: u32[rings] point counts, u32[rings] 1 for a hole, zero bytes to a multiple of
//            8, then f64 [z, x] pairs of every ring in turn (X a diameter)
// web/src/stock.js reads it.
#include <cstdint>
#include <string>
#include <vector>

#include "sim/stock_model.hpp"

namespace ncvm::server {

class StockSnapshots {
 public:
  StockSnapshots(int maxGrid, uint64_t every, size_t keep);
  // Called before the stock model takes each move (Session::watchStock): `moves` have been cut.
  void offer(StockModel& model, uint64_t moves);
  // The kind 6 frames, in the order of k.
  std::vector<std::string> frames() const;
  uint64_t every() const { return every_; }
  size_t count() const { return shots_.size(); }

  static std::string payload(const ViewerStockData& stock, uint64_t moves);

 private:
  struct Shot {
    uint64_t moves;
    std::string payload;
  };
  int maxGrid_;
  uint64_t every_;
  size_t keep_;
  std::vector<Shot> shots_;
};

}  // namespace ncvm::server
