#include "server/stock_snapshots.hpp"

#include <algorithm>
#include <cstring>

#include "server/viewer_stream.hpp"

namespace ncvm::server {

namespace {

template <class T>
void put(std::string& out, const T* data, size_t count) {
  const size_t at = out.size();
  out.resize(at + count * sizeof(T));
  if (count) std::memcpy(out.data() + at, data, count * sizeof(T));
}

void put32(std::string& out, std::initializer_list<uint32_t> values) {
  put(out, values.begin(), values.size());
}

}  // namespace

StockSnapshots::StockSnapshots(int maxGrid, uint64_t every, size_t keep)
    : maxGrid_(maxGrid), every_(std::max<uint64_t>(1, every)), keep_(std::max<size_t>(2, keep)) {}

void StockSnapshots::offer(StockModel& model, uint64_t moves) {
  if (moves % every_ != 0) return;
  shots_.push_back({moves, payload(model.viewerSnapshot(maxGrid_), moves)});
  if (shots_.size() <= keep_) return;
  every_ *= 2;
  std::erase_if(shots_, [this](const Shot& s) { return s.moves % every_ != 0; });
}

std::vector<std::string> StockSnapshots::frames() const {
  std::vector<std::string> out;
  out.reserve(shots_.size());
  for (const Shot& s : shots_) out.push_back(frame(FrameKind::Stock, s.payload));
  return out;
}

std::string StockSnapshots::payload(const ViewerStockData& d, uint64_t moves) {
  std::string out;
  const auto lo = static_cast<uint32_t>(moves), hi = static_cast<uint32_t>(moves >> 32);
  if (d.grid) {
    put32(out, {lo, hi, 0, static_cast<uint32_t>(d.nx), static_cast<uint32_t>(d.ny),
                static_cast<uint32_t>(d.step), 0, 0});
    const double box[] = {d.x0, d.y0, d.x1, d.y1, d.cell, d.top, d.bottom};
    put(out, box, 7);
    put(out, d.z.data(), d.z.size());
    return out;
  }
  const auto rings = static_cast<uint32_t>(d.rings.size());
  put32(out, {lo, hi, 1, rings, 0, 0, 0, 0});
  for (const auto& r : d.rings) put32(out, {static_cast<uint32_t>(r.zx.size() / 2)});
  for (const auto& r : d.rings) put32(out, {r.hole ? 1u : 0u});
  out.resize((out.size() + 7) / 8 * 8, '\0');
  for (const auto& r : d.rings) put(out, r.zx.data(), r.zx.size());
  return out;
}

}  // namespace ncvm::server
