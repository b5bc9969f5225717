#include "timing/hole_tracker.hpp"

#include <cmath>

namespace ncvm {

namespace {
constexpr double kEps = 1e-6;
}

DrillMove DrillMove::of(const MoveEvent& e) {
  DrillMove m;
  m.rapid = e.mode == MoveMode::Rapid;
  m.x = e.start[0], m.y = e.start[1], m.z0 = e.start[2], m.z1 = e.end[2];
  bool straight = e.mode == MoveMode::Rapid || e.mode == MoveMode::Linear;
  m.alongZ = straight && std::fabs(e.end[0] - e.start[0]) < kEps &&
             std::fabs(e.end[1] - e.start[1]) < kEps;
  for (size_t k = 3; k < kMaxAxes && m.alongZ; ++k)
    m.alongZ = std::fabs(e.end[k] - e.start[k]) < kEps;
  return m;
}

void HoleTracker::move(const DrillMove& m, double model, double simple, uint32_t op) {
  bool feedDown = !m.rapid && m.alongZ && m.z1 < m.z0 - kEps;
  if (open_) {
    bool atHole = m.alongZ && std::fabs(m.x - x_) < kEps && std::fabs(m.y - y_) < kEps;
    if (!atHole) {
      close();
    } else if (feedDown) {
      if (retracted_) {
        ++feeds_;
        if (toTop_) ++full_;
        retracted_ = toTop_ = false;
      }
      commit(model, simple);
      awaitingTop_ = true;
      return;
    } else if (m.z1 > m.z0 + kEps) {
      retracted_ = everRetracted_ = true;
      if (m.z1 >= top_ - kEps) {
        toTop_ = true;
        if (awaitingTop_) {
          commit(model, simple);
          awaitingTop_ = false;
          return;
        }
      }
      pending_.add(model, simple);
      return;
    } else {
      pending_.add(model, simple);  // back down inside the hole (G83's rapid to d above)
      return;
    }
  }
  if (feedDown) open(m, model, simple, op);
}

void HoleTracker::open(const DrillMove& m, double model, double simple, uint32_t op) {
  open_ = true;
  op_ = op;
  x_ = m.x, y_ = m.y, top_ = m.z0;
  feeds_ = 1, full_ = 0;
  retracted_ = toTop_ = everRetracted_ = false;
  awaitingTop_ = true;
  time_ = TimePair{model, simple};
  pending_ = {};
}

void HoleTracker::close() {
  if (!open_) return;
  open_ = false;
  if (!everRetracted_) return;  // a plunge the tool left sideways: no hole
  // Still in the hole when it closes (no retract to the top after the last feed): all of it.
  if (awaitingTop_) time_.add(pending_);
  uint64_t pecks = feeds_ > 1 ? feeds_ : 0;
  ++stats_.holes;
  stats_.pecks += pecks;
  stats_.fullRetracts += full_;
  Place key{op_, std::llround(x_ * 1000.0), std::llround(y_ * 1000.0)};
  HoleTime* h = nullptr;
  if (auto it = index_.find(key); it != index_.end()) {
    h = &holes_[it->second];
  } else if (holes_.size() < kMaxListed) {
    index_.emplace(key, static_cast<uint32_t>(holes_.size()));
    h = &holes_.emplace_back();
    h->op = op_, h->x = x_, h->y = y_;
  }
  if (!h) {
    ++unlisted_;
    return;
  }
  h->time.add(time_);
  h->pecks += pecks;
  h->fullRetracts += full_;
  ++h->runs;
}

}  // namespace ncvm
