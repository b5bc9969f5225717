// A block's words, read and checked before anything of the block takes effect (gatherWords,
// and its short form for plain CAM lines), and the macro calls they make: G65/G66 arguments
// and the G/M/T code calls of parameters 6050-6089 (nc_block.cpp runs the block with them).
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"

namespace ncvm {

namespace {
constexpr uint32_t bit(char letter) {
  return Words::bit(letter);
}

// Type I argument letters -> local variable (fanuc-reference B.7). 0 = not an argument.
constexpr int kArgVar[26] = {
    /*A*/ 1,  /*B*/ 2,  /*C*/ 3,  /*D*/ 7,  /*E*/ 8,  /*F*/ 9,  /*G*/ 0,  /*H*/ 11, /*I*/ 4,
    /*J*/ 5,  /*K*/ 6,  /*L*/ 0,  /*M*/ 13, /*N*/ 0,  /*O*/ 0,  /*P*/ 0,  /*Q*/ 17, /*R*/ 18,
    /*S*/ 19, /*T*/ 20, /*U*/ 21, /*V*/ 22, /*W*/ 23, /*X*/ 24, /*Y*/ 25, /*Z*/ 26};
}  // namespace

// The words of a block the compiler marked plain (kPlainBlock): literals, each letter once,
// at most one G (G00-G03), no M, name or comma word, none long enough for the digit check,
// so of gatherWords' work only the values, points and columns are left.
void Executor::gatherPlainWords(const Block& b, Words& w) const {
  const Word* words = frames_.back().prog->words.data() + b.firstWord;
  for (uint32_t k = 0; k < b.nWords; ++k) {
    const Word& wd = words[k];
    if (wd.letter == 'G') {
      w.g[0] = static_cast<int16_t>(wd.value * 10.0);
      w.gcol[0] = wd.col;
      w.ng = 1;
      continue;
    }
    const auto idx = static_cast<size_t>(wd.letter - 'A');
    w.present |= bit(wd.letter);
    if (wd.flags & kHasPoint) w.point |= bit(wd.letter);
    w.val[idx] = wd.value;
    w.col[idx] = wd.col;
  }
}

void Executor::gatherWords(const Block& b, Words& w) {
  const Program& p = *frames_.back().prog;
  const Word* words = p.words.data() + b.firstWord;
  bool longNumbers = false;
  for (uint32_t k = 0; k < b.nWords; ++k) {
    const Word& wd = words[k];
    double v = 0;
    bool point = wd.flags & kHasPoint;
    switch (wd.kind) {
      case WordKind::Literal:
        if (wd.letter == '<') {
          w.nameIdx = wd.a;
          continue;
        }
        v = wd.value;
        longNumbers |= (wd.flags & kLongNumber) != 0;
        break;
      case WordKind::Var:
      case WordKind::NegVar: {
        Value x = readVar(wd.a);
        if (x.null) continue;  // a vacant variable drops the whole word
        v = wd.kind == WordKind::NegVar ? -x.v : x.v;
        point = true;
        break;
      }
      case WordKind::Expr: {
        Value x = evalAddress(wd.a, wd.letter);
        if (x.null) continue;
        v = x.v;
        point = true;
        break;
      }
    }
    if (!std::isfinite(v) || std::fabs(v) > 1e12) {
      AlarmError e(AlarmId::FloatOverflow, fmt::format("{} value out of range", wd.letter));
      e.col = wd.col;
      throw e;
    }
    char L = wd.letter;
    if (L == 'a') {
      w.hasCommaA = true;
      w.commaAngle = v;
      w.commaACol = wd.col;
      continue;
    }
    if (L == 'c' || L == 'r') {
      // ,C and ,R: one of them per block (PS0053 on the control; the later one wins here).
      w.hasCommaC = L == 'c';
      w.hasCommaR = L == 'r';
      w.commaValue = v;
      w.commaPoint = point;
      w.commaCol = wd.col;
      continue;
    }
    if (L == 'G') {
      int code10 = static_cast<int>(std::llround(v * 10.0));
      // A G code number the control lacks is still legal when a parameter (6050-6059)
      // makes it call a macro; codeCall() or the modal loop decide.
      bool called =
          code10 % 10 == 0 && code10 < 10000 && gCall_[static_cast<size_t>(code10 / 10)] > 0;
      if (w.ng >= static_cast<int>(w.g.size()) || code10 < 0 || code10 >= 10000 ||
          (!gInfo(code10) && !called)) {
        AlarmError e(AlarmId::ImproperGCode, fmt::format("G{}", v));
        e.col = wd.col;
        throw e;
      }
      w.g[static_cast<size_t>(w.ng)] = static_cast<int16_t>(code10);
      w.gcol[static_cast<size_t>(w.ng++)] = wd.col;
      continue;
    }
    if (L == 'M') {
      if (w.nm >= static_cast<int>(w.m.size())) {
        AlarmError e(AlarmId::ImproperAddress, "more than three M codes in a block");
        e.col = wd.col;
        throw e;
      }
      w.m[static_cast<size_t>(w.nm++)] = static_cast<int32_t>(std::llround(v));
    }
    int idx = L - 'A';
    if (w.present & bit(L)) w.twice |= bit(L);
    w.present |= bit(L);
    w.val[static_cast<size_t>(idx)] = v;
    if (point)
      w.point |= bit(L);
    else
      w.point &= ~bit(L);
    w.col[static_cast<size_t>(idx)] = wd.col;
    if (L != 'G' && L != 'L' && L != 'N' && L != 'O' && L != 'P' &&
        w.nArgs < static_cast<int>(w.args.size()))
      w.args[static_cast<size_t>(w.nArgs++)] = Words::Arg{L, v, point};
  }
  if (longNumbers) {
    bool macroCall = false;
    for (int k = 0; k < w.ng; ++k) {
      const int g = w.g[static_cast<size_t>(k)];
      macroCall |= g == 650 || g == 660 || g == 661 ||
                   (g % 10 == 0 && g < 10000 && gCall_[static_cast<size_t>(g / 10)] > 0);
    }
    for (int k = 0; k < w.nm; ++k) {
      const int m = w.m[static_cast<size_t>(k)];
      macroCall |= m > 0 && m < 1000 && mMacroCall_[static_cast<size_t>(m)] > 0;
    }
    for (uint32_t k = 0; k < b.nWords; ++k)
      if (words[k].flags & kLongNumber) checkDigits(words[k], macroCall);
  }
}

// Argument specification I and II in one pass (fanuc-reference B.7): I/J/K open a new set
// when the same or an earlier letter of I-J-K appears again; a later letter overrides an
// earlier one on the same variable. `callingM` is the M code of an M-code call, which is
// not an argument.
void Executor::buildArgs(const Words& w, int callingM, std::array<Value, 33>& args,
                         std::array<double, 33>& scale) const {
  args.fill(Value{});
  scale.fill(0);
  int set = 0, lastIjk = 3;
  for (int k = 0; k < w.nArgs; ++k) {
    const Words::Arg& a = w.args[static_cast<size_t>(k)];
    if (a.letter == 'M' && callingM >= 0 && std::llround(a.value) == callingM) {
      callingM = -1;
      continue;
    }
    int var = kArgVar[a.letter - 'A'];
    if (a.letter == 'I' || a.letter == 'J' || a.letter == 'K') {
      int idx = a.letter - 'I';
      if (set == 0 || idx <= lastIjk) ++set;
      lastIjk = idx;
      if (set > 10) throw AlarmError(AlarmId::MacroStatementFormat, "more than 10 I/J/K sets");
      var = 3 * set + 1 + idx;
    }
    if (var == 0) continue;
    double v = a.value;
    double undo = 0;
    if (!a.point && !dpi_ && std::strchr("XYZIJKRQUVWABC", a.letter)) {
      // An argument without a decimal point is a count of least increments.
      bool angular = a.letter == 'A' || a.letter == 'B' || a.letter == 'C';
      double lii = leastIncrement(setup_.increment, angular ? InputUnit::Mm : modal_.unit);
      v = a.value * lii;
      undo = 1.0 / lii;
    }
    args[static_cast<size_t>(var - 1)] = Value::num(v);
    scale[static_cast<size_t>(var - 1)] = undo;
  }
}

void Executor::macroCallFromWords(const Program* p, int repeats, const Words& w, FrameKind kind,
                                  bool codeCalled, int callingM) {
  std::array<Value, 33> args;
  std::array<double, 33> scale;
  buildArgs(w, callingM, args, scale);
  callMacro(p, repeats, args, scale, kind, codeCalled);
}

// G/M/T codes that call programs by parameter (fanuc-reference B.7). Returns true when the
// block became a call.
bool Executor::codeCall(const Block& b, Words& w) {
  (void)b;
  for (int k = 0; k < w.ng; ++k) {
    int g = w.g[static_cast<size_t>(k)];
    if (g % 10 != 0) continue;
    int prog = g < 10000 ? gCall_[static_cast<size_t>(g / 10)] : 0;
    if (prog <= 0) continue;
    ++frames_.back().pc;
    macroCallFromWords(findProgram(prog, -1), w.has('L') ? integerWord(w, 'L') : 1, w,
                       FrameKind::Macro, true);
    return true;
  }
  for (int k = 0; k < w.nm; ++k) {
    int m = w.m[static_cast<size_t>(k)];
    if (int prog = m >= 0 && m < 1000 ? mMacroCall_[static_cast<size_t>(m)] : 0; prog > 0) {
      ++frames_.back().pc;
      macroCallFromWords(findProgram(prog, -1), 1, w, FrameKind::Macro, true, m);
      return true;
    }
  }
  return false;
}

}  // namespace ncvm
