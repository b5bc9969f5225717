#pragma once
// Where the time goes: totals, and breakdowns per block type, per tool, per operation (the
// blocks between tool changes and operation comments) and per program line, each with the
// modelled time and the plain length / feed time beside it; plus the holes drilled, each with
// its time, pecks and full retracts (hole_tracker.hpp), so two drilling strategies can be
// compared.
#include <bit>
#include <cstdint>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <unordered_map>
#include <vector>

#include "canon/events.hpp"
#include "core/source.hpp"
#include "timing/hole_tracker.hpp"

namespace ncvm {

enum class TimeKind : uint8_t { Rapid, Cutting, Dwell, Auxiliary };
constexpr int kTimeKinds = 4;
const char* timeKindName(TimeKind k);

struct ToolTime {
  int tool = 0;
  TimePair time;
};

// An operation is a place in the program: the tool change (with its tool) or the operation
// comment that starts it (the rule: docs/setup-format.md [timing] operation_comments). When
// the program passes that place again (an M99 loop, a bar feeder's next part, a GOTO back)
// the same operation goes on: the report holds one entry per place, whatever the run length.
struct OperationTime {
  int tool = 0;
  EventOrigin first;       // the block that started it (tool change, comment), or the program start
  std::string label;       // the comment that named it (empty: none)
  bool byComment = false;  // started by a comment
  uint64_t moves = 0;      // moves and dwells
  uint64_t runs = 1;       // times the program entered it
  TimePair time;
  double rapidLength = 0, feedLength = 0;
  std::array<TimePair, kTimeKinds> byKind{};
};

struct LineTime {
  EventOrigin at;
  uint64_t count = 0;
  TimePair time;
};

class TimeReport {
 public:
  void addMove(const MoveEvent& e, double model, double simple) {
    addMoveTime(e.mode, e.at, e.length, model, simple);
    addDrillMove(DrillMove::of(e), model, simple);
  }
  // addMove in two halves, for the look-ahead that holds compact records rather than events:
  // the move's time, and the move as the hole tracker sees it, with the same time (called in
  // the order of the moves, when it is planned).
  void addMoveTime(MoveMode mode, const EventOrigin& at, double length, double model,
                   double simple);
  void addDrillMove(const DrillMove& m, double model, double simple) {
    holes_.move(m, model, simple, static_cast<uint32_t>(cur_));
  }
  // The program ended (the hole the tool is in closes).
  void finish() { holes_.finish(); }
  // addMoveTime in two halves again, for a run of cutting moves planned as one profile: each
  // block's time on its line, then the run's sums once.
  void addLineTime(const EventOrigin& at, double model, double simple) {
    addLine(at, model, simple);
  }
  void addCutting(double model, double simple, double length, uint64_t moves);
  void add(TimeKind kind, const EventOrigin& at, double model, double simple);
  void toolSelected(int tool, const EventOrigin& at);
  // A comment alone on its line (operations by comment, docs/setup-format.md [timing]).
  void commentSeen(std::string_view text, const EventOrigin& at);

  const TimePair& total() const { return total_; }
  const TimePair& byKind(TimeKind k) const { return byKind_[static_cast<size_t>(k)]; }
  const std::vector<OperationTime>& operations() const { return ops_; }
  const DrillStats& drilling() const { return holes_.stats(); }
  // The holes by operation and position (at most HoleTracker::kMaxListed; holesUnlisted()
  // counts the rest).
  const std::vector<HoleTime>& holes() const { return holes_.holes(); }
  uint64_t holesUnlisted() const { return holes_.unlisted(); }
  std::vector<ToolTime> byTool() const;
  // The per-line table keeps times and counts only (20 bytes a line); where a line is (its
  // program and N number) comes from this for the few lines reported. Without it the top
  // blocks have no program and N.
  using LineOrigin =
      std::function<void(uint32_t file, uint32_t line, const std::string*& program, int32_t& n)>;
  std::vector<LineTime> topLines(size_t n, const LineOrigin& origin = {}) const;
  // The number of lines of each file (by file id): a file's table is allocated once, at its
  // size, when its first line runs (otherwise it grows by doubling).
  void setLineCounts(std::vector<uint32_t> counts) { lineCounts_ = std::move(counts); }

  nlohmann::json toJson(const SourceFiles& files, bool dynamic, size_t topN = 10,
                        const LineOrigin& origin = {}) const;

 private:
  OperationTime& op();
  // The places that start an operation (a comment's key has no tool), and entering one.
  struct PlaceKey {
    uint32_t file = 0, line = 0;
    int32_t tool = 0;
    bool operator==(const PlaceKey&) const = default;
  };
  struct PlaceHash {
    size_t operator()(const PlaceKey& k) const {
      return std::hash<uint64_t>{}((uint64_t{k.file} << 32 | k.line) ^
                                   (static_cast<uint64_t>(static_cast<uint32_t>(k.tool)) << 20));
    }
  };
  static constexpr int32_t kCommentPlace = std::numeric_limits<int32_t>::min();
  bool enterPlace(const PlaceKey& k);
  void startOperation(int tool, const EventOrigin& at, const PlaceKey& k);
  void moved(OperationTime& o, uint64_t moves) {
    o.moves += moves;
    curMoved_ = curMoved_ || moves > 0;
  }
  void addLine(const EventOrigin& at, double model, double simple) {
    if (at.file >= lines_.size() || at.line >= lines_[at.file].count.size()) [[unlikely]]
      growLines(at);
    LineTable& t = lines_[at.file];
    if (std::bit_cast<uint64_t>(model) != std::bit_cast<uint64_t>(simple) || !t.simple.empty())
        [[unlikely]]
      addSimple(t, at.line, simple);
    t.model[at.line] += model;
    ++t.count[at.line];
  }
  void growLines(const EventOrigin& at);

  TimePair total_;
  std::array<TimePair, kTimeKinds> byKind_{};
  std::vector<OperationTime> ops_;
  std::unordered_map<PlaceKey, uint32_t, PlaceHash> places_;  // place -> ops_ index
  size_t cur_ = 0;         // the operation running (ops_ index, when ops_ is not empty)
  bool curMoved_ = false;  // it moved (or dwelt) since the program entered it
  int tool_ = 0;
  // Per file, per line (lines are dense: vectors, not a map); file and line are the indexes.
  // All zero until a block of the line runs, so the table grows by a plain memset.
  // In the simple model (the default) every move's model time is its simple time, bit for
  // bit, so the sums are too: `simple` stays empty (8 bytes a line fewer to allocate and
  // clear) until the first time the two differ; it then starts as a copy of `model`.
  struct LineTable {
    std::vector<double> model, simple;
    std::vector<uint32_t> count;
    double simpleAt(size_t line) const { return simple.empty() ? model[line] : simple[line]; }
  };
  static void addSimple(LineTable& t, uint32_t line, double simple);
  std::vector<LineTable> lines_;
  std::vector<uint32_t> lineCounts_;
  HoleTracker holes_;
};

}  // namespace ncvm
