#include "sim/mill_sim.hpp"

#include <algorithm>
#include <cmath>
#include <thread>

namespace ncvm {

MillSim::MillSim(HeightField field, int threads) : field_(std::move(field)) {
  int hw = static_cast<int>(std::thread::hardware_concurrency());
  threads_ = threads > 0 ? threads : std::max(1, hw);
  // More threads than stripes would leave some idle.
  int stripes = (field_.ny() >> Stripe::kStripeShift) + 1;
  threads_ = std::min(threads_, stripes);
  ops_.reserve(kBatch);
}

void MillSim::push(const Op& op) {
  ++moves_;
  ops_.push_back(op);
  // Every op cuts its tool at its end point, so the next one starting there may skip the
  // cells where its start is lowest (sweepLine's startCut).
  ops_.back().startCut = lastTool_ == op.tool && continuesFrom(lastEnd_, op.a);
  lastTool_ = op.tool;
  lastEnd_ = op.b;
  if (ops_.size() >= kBatch) flush();
}

void MillSim::line(const Point3& a, const Point3& b, bool rapid, uint32_t tag) {
  if (!tool_) return;
  push(Op{tool_, a, b, 0, 0, 0, 0, 0, tag, rapid, false});
}

void MillSim::arcXY(double cx, double cy, double radius, double a0, double sweep, double z0,
                    double z1, bool rapid, uint32_t tag) {
  if (!tool_) return;
  auto at = [&](double ang, double z) {
    return Point3{cx + radius * std::cos(ang), cy + radius * std::sin(ang), z};
  };
  if (!(radius > 0)) return line(at(a0, z0), at(a0 + sweep, z1), rapid, tag);
  if (std::abs(z1 - z0) <= 1e-9) {
    push(Op{tool_, at(a0, z0), at(a0 + sweep, z0), cx, cy, radius, a0, sweep, tag, rapid, true});
    return;
  }
  // Helix: chords whose sagitta stays within chordTol.
  double step = 2 * std::acos(std::max(0.0, 1 - chordTol / radius));
  int n = std::max(1, static_cast<int>(std::ceil(std::abs(sweep) / std::max(step, 1e-4))));
  Point3 prev = at(a0, z0);
  for (int k = 1; k <= n; ++k) {
    double u = static_cast<double>(k) / n;
    Point3 next = at(a0 + u * sweep, z0 + u * (z1 - z0));
    push(Op{tool_, prev, next, 0, 0, 0, 0, 0, tag, rapid, false});
    prev = next;
  }
}

// One thread's share of the batch: every op on this thread's stripes, in order.
void MillSim::run(int index, std::vector<float>& pen) {
  Stripe s{index, threads_};
  // No cell is above the block's top (cuts only lower it), so a tool, shank or holder whose
  // lowest point stays at or above it touches nothing: air moves, rapids at a safe height and
  // holders high over the part cost no cell visits.
  const double top = field_.top();
  for (size_t k = 0; k < ops_.size(); ++k) {
    const Op& op = ops_[k];
    const MillTool& t = *op.tool;
    const double lowest = std::min(op.a[2], op.b[2]);
    // Shank and holder against the stock as the move finds it (before it cuts). A rapid's
    // cutter contact is already a collision, so only feed moves check the shank.
    // Arcs: the flat-bottomed cylinder swept along the same arc, measured only.
    auto part = [&](double r, double lift) {
      if (!op.arc) return holderPenetration(field_, r, lift, op.a, op.b, s);
      MillTool cyl;
      cyl.radius = r;
      return sweepArcXY(field_, cyl, op.cx, op.cy, op.radius, op.a0, op.sweep, op.a[2] + lift, s,
                        SweepMode::Measure);
    };
    if (!op.rapid && t.fluteLength > 0 && lowest + t.fluteLength < top)
      pen[3 * k + 1] = part(t.radius, t.fluteLength);
    if (t.holderRadius > 0 && lowest + t.holderZ < top)
      pen[3 * k + 2] = part(t.holderRadius, t.holderZ);
    if (lowest >= top) continue;  // pen stays 0
    float cut = op.arc ? sweepArcXY(field_, t, op.cx, op.cy, op.radius, op.a0, op.sweep, op.a[2], s)
                       : sweepLine(field_, t, op.a, op.b, s, SweepMode::Cut, op.startCut);
    pen[3 * k] = cut;
  }
}

void MillSim::flush() {
  if (ops_.empty()) return;
  std::vector<std::vector<float>> pens(static_cast<size_t>(threads_),
                                       std::vector<float>(3 * ops_.size(), 0.0f));
  std::vector<std::thread> pool;
  for (int k = 1; k < threads_; ++k) pool.emplace_back([this, k, &pens] { run(k, pens[k]); });
  run(0, pens[0]);
  for (auto& th : pool) th.join();
  for (size_t k = 0; k < ops_.size(); ++k) {
    for (int what = 0; what < 3; ++what) {
      float depth = 0;
      for (const auto& p : pens) depth = std::max(depth, p[3 * k + what]);
      if (what == 0 && depth > 0 && (!anyCut_ || lastCutTag_ != ops_[k].tag)) {
        ++cuttingMoves_;
        anyCut_ = true;
        lastCutTag_ = ops_[k].tag;
      }
      if (depth > kContactDepth && (what != 0 || ops_[k].rapid))
        contacts_.push_back({static_cast<MillContact::Kind>(what), ops_[k].tag, depth});
    }
  }
  ops_.clear();
}

}  // namespace ncvm
