#pragma once
// The holes a program drills, seen in its moves, with the time each takes and its pecks, so
// two drilling strategies can be compared hole by hole (ncvm compare).
//
// A hole opens with a feed along -Z alone (X, Y and every other axis fixed). It is a hole
// once the tool retracts along Z at the same X Y (rapid or feed): a pocket's plunge, followed
// by a cut sideways at depth, is none. It closes when the tool leaves its X Y (or the program
// ends). A peck is a feed into the hole after a retract within it; a hole with one is peck
// drilled, and all its feeds, the first included, are its pecks (as Q counts them). A hole
// drilled in one feed has no pecks. A full retract is one back to (or above) the level its
// first feed started from (the R plane) between two pecks; the last retract out of the hole
// is not one. A hole's time runs from its first feed to the first retract to that level
// after its last feed (the final retract out included, what follows at the same X Y not).
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <vector>

#include "canon/events.hpp"

namespace ncvm {

struct TimePair {
  double model = 0, simple = 0;
  void add(double m, double s) { model += m, simple += s; }
  void add(const TimePair& t) { add(t.model, t.simple); }
};

struct DrillStats {
  uint64_t holes = 0, pecks = 0, fullRetracts = 0;
};

// What the tracker needs of a move (a few words: the time stage holds it for each move in
// its look-ahead).
struct DrillMove {
  bool rapid = false;
  bool alongZ = false;  // a straight move along Z alone
  double x = 0, y = 0, z0 = 0, z1 = 0;
  static DrillMove of(const MoveEvent& e);
};

// One hole, by operation and position; drilled again (a loop), it adds to the same entry.
struct HoleTime {
  uint32_t op = 0;  // TimeReport::operations() index
  double x = 0, y = 0;
  TimePair time;
  uint64_t pecks = 0, fullRetracts = 0, runs = 0;
};

class HoleTracker {
 public:
  // At most this many holes are listed (one program drilling more, in a loop moving X,
  // still counts them all in stats()).
  static constexpr size_t kMaxListed = 10000;

  // A move in time order, with its times; op: the operation it belongs to.
  void move(const DrillMove& m, double model, double simple, uint32_t op);
  // Time spent while the tool may be in a hole (a dwell, an M function, a tool change).
  void other(double model, double simple) {
    if (open_) pending_.add(model, simple);
  }
  // The program ended: the open hole closes.
  void finish() { close(); }

  const DrillStats& stats() const { return stats_; }
  const std::vector<HoleTime>& holes() const { return holes_; }
  uint64_t unlisted() const { return unlisted_; }

 private:
  void open(const DrillMove& m, double model, double simple, uint32_t op);
  void close();
  void commit(double model, double simple) {
    time_.add(pending_);
    time_.add(model, simple);
    pending_ = {};
  }

  DrillStats stats_;
  std::vector<HoleTime> holes_;
  // (op, x, y on a 1 µm grid) -> holes_ index.
  struct Place {
    uint32_t op = 0;
    int64_t x = 0, y = 0;
    bool operator==(const Place&) const = default;
  };
  struct PlaceHash {
    size_t operator()(const Place& p) const {
      return std::hash<int64_t>{}(p.x * 1000003 ^ p.y * 7919 ^ int64_t{p.op} << 40);
    }
  };
  std::unordered_map<Place, uint32_t, PlaceHash> index_;
  uint64_t unlisted_ = 0;
  // The open hole.
  bool open_ = false;
  uint32_t op_ = 0;
  double x_ = 0, y_ = 0, top_ = 0;
  uint64_t feeds_ = 0, full_ = 0;
  bool retracted_ = false;  // since the last feed
  bool toTop_ = false;      // ... back to the top level
  bool everRetracted_ = false;
  bool awaitingTop_ = false;  // a feed came, its retract to the top level not yet
  TimePair time_, pending_;
};

}  // namespace ncvm
