#pragma once
// Where the stock sits on the machine (stock.frame, docs/setup-format.md). The moves come in
// work coordinates of the system in use; the stock is a piece of material clamped on the
// machine, so when a program moves work zero (a probing macro writing #5221, G10, G52, G92,
// another G54-G59) after it has begun to cut, the moves must be shifted by how far work zero
// moved, or the stock would move with the offsets.
//   "work"    (default) the coordinates of the work system the program first cuts in: the
//             stock follows work zero until the first feed move (a program sets up its
//             coordinates before it cuts) and stays fixed on the machine from then on.
//   "machine" machine coordinates of the tool tip (work zero counts from the start).
//   "program" the program's coordinates at every moment: the stock follows every change of
//             work zero (old lathe programs that set each tool's coordinates by G50).
#include <array>
#include <string>

#include "canon/events.hpp"
#include "machine/setup.hpp"

namespace ncvm {

class StockFrame {
 public:
  enum class Kind { Work, Machine, Program };
  // unitsPerMm: 1, or 1 / 25.4 for an inch stock; diameterX: MoveEvent X is a diameter.
  StockFrame(Kind kind, double unitsPerMm, bool diameterX)
      : kind_(kind), unit_(unitsPerMm), diameterX_(diameterX), fixed_(kind != Kind::Work) {}

  // The setup's stock.frame, in the setup's units; throws SetupError for another name.
  StockFrame(const Setup& setup, bool diameterX)
      : StockFrame(kindOf(setup.stock), setup.initialUnit == InputUnit::Inch ? 1 / 25.4 : 1.0,
                   diameterX) {}

  // Name check for the setup ("work", "machine", "program"); false for any other.
  static bool parse(const std::string& name, Kind& kind) {
    if (name == "work")
      kind = Kind::Work;
    else if (name == "machine")
      kind = Kind::Machine;
    else if (name == "program")
      kind = Kind::Program;
    else
      return false;
    return true;
  }

  static Kind kindOf(const StockSpec& st) {
    Kind k{};
    if (!parse(st.frame, k))
      throw SetupError(
          "stock: frame takes \"work\", \"machine\" or \"program\" (not a work offset)",
          "stock.frame", st.line);
    return k;
  }

  void origin(const WorkOriginEvent& e) {
    now_ = e.mm;
    if (!fixed_) placed_ = now_;
    update();
  }

  // Call for every move before place(): a "work" stock is fixed at the first feed move.
  void move(const MoveEvent& e) {
    if (!fixed_ && e.mode != MoveMode::Rapid) fixed_ = true;
  }

  // Stock coordinates = work coordinates + shift (program units, X Y Z, X as a radius).
  const std::array<double, 3>& shift() const { return shift_; }
  bool shifted() const { return shifted_; }

  // The move in stock coordinates: `e` itself when nothing is shifted, else a copy in
  // `scratch` (every work-coordinate field moved; machine coordinates stay).
  const MoveEvent& place(const MoveEvent& e, MoveEvent& scratch) const {
    if (!shifted_) return e;
    scratch = e;
    const double dx = diameterX_ ? 2 * shift_[0] : shift_[0];
    auto add = [&](AxisArray& a) {
      a[0] += dx;
      a[1] += shift_[1];
      a[2] += shift_[2];
    };
    add(scratch.start);
    add(scratch.end);
    add(scratch.programmedEnd);
    add(scratch.noseEnd);
    for (int k = 0; k < scratch.pathPoints; ++k) add(scratch.path[static_cast<size_t>(k)]);
    scratch.center[0] += dx;
    scratch.center[1] += shift_[1];
    scratch.center[2] += shift_[2];
    return scratch;
  }

 private:
  void update() {
    shifted_ = false;
    for (size_t k = 0; k < 3; ++k) {
      shift_[k] = kind_ == Kind::Program   ? 0.0
                  : kind_ == Kind::Machine ? now_[k] * unit_
                                           : (now_[k] - placed_[k]) * unit_;
      shifted_ |= shift_[k] != 0;
    }
  }

  Kind kind_;
  double unit_;
  bool diameterX_;
  bool fixed_;
  std::array<double, 3> now_{}, placed_{}, shift_{};
  bool shifted_ = false;
};

}  // namespace ncvm
