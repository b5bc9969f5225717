// Lathe canned cycles in the control: read the cycle words (and for G70-G73 the P..Q
// contour blocks), hand them to the planners of src/motion/lathe_cycles, and make the
// moves they return. Numbering follows the G-code system (A/B: G70-G76, G90/G92/G94 or
// G77/G78/G79; C: G72-G78, G20/G21/G24).
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"
#include "motion/lathe_cycles.hpp"

namespace ncvm {

int Executor::latheCycleKind(int code10) const {
  if (!lathe_) return 0;
  bool c = series_ == Series::TC;
  switch (code10) {
    case 700:
      return c ? 0 : kFinish;
    case 710:
      return c ? 0 : kRoughTurn;
    case 720:
      return c ? kFinish : kRoughFace;
    case 730:
      return c ? kRoughTurn : kPattern;
    case 740:
      return c ? kRoughFace : kFacePeck;
    case 750:
      return c ? kPattern : kGroove;
    case 760:
      return c ? kFacePeck : kMultiThread;
    case 770:
      return c ? kGroove : (series_ == Series::TB ? kTurn : 0);
    case 780:
      return c ? kMultiThread : (series_ == Series::TB ? kThread : 0);
    case 790:
      return series_ == Series::TB ? kFace : 0;
    case 900:
      return series_ == Series::TA ? kTurn : 0;
    case 920:
      return series_ == Series::TA ? kThread : 0;
    case 940:
      return series_ == Series::TA ? kFace : 0;
    case 200:
      return c ? kTurn : 0;
    case 210:
      return c ? kThread : 0;
    case 240:
      return c ? kFace : 0;
    default:
      return 0;
  }
}

namespace {
double unitNm(InputUnit u) {
  return u == InputUnit::Inch ? 25.4e6 : 1e6;
}
}  // namespace

// Positions in the planners' terms: (x radius, z) in program units.
lathe::Pt Executor::latheHere() const {
  double u = unitNm(modal_.unit);
  return {static_cast<double>(machine_[0] - offset_[0]) / u,
          static_cast<double>(machine_[2] - offset_[2]) / u};
}

// The end point of a cycle block: X (diameter) or U, Z or W; G91 in systems B/C.
lathe::Pt Executor::latheTarget(const Words& w, const lathe::Pt& from) const {
  double u = unitNm(modal_.unit);
  lathe::Pt p = from;
  if (w.has('X')) {
    double x = static_cast<double>(lengthNm(w.value('X'), w.hasPoint('X'), 0)) / 2.0 / u;
    p.x = modal_.incremental ? from.x + x : x;
  }
  if (w.has('U'))
    p.x = from.x + static_cast<double>(lengthNm(w.value('U'), w.hasPoint('U'), 0)) / 2.0 / u;
  if (w.has('Z')) {
    double z = static_cast<double>(lengthNm(w.value('Z'), w.hasPoint('Z'), 2)) / u;
    p.z = modal_.incremental ? from.z + z : z;
  }
  if (w.has('W'))
    p.z = from.z + static_cast<double>(lengthNm(w.value('W'), w.hasPoint('W'), 2)) / u;
  return p;
}

double Executor::latheLength(const Words& w, char letter, bool diameter) const {
  double v =
      static_cast<double>(lengthNm(w.value(letter), w.hasPoint(letter), 2)) / unitNm(modal_.unit);
  return diameter ? v / 2.0 : v;
}

// P and Q of G74-G76 are integer counts of least increments (no decimal point).
double Executor::latheIncrements(const Words& w, char letter) const {
  return std::fabs(static_cast<double>(std::llround(w.value(letter)))) *
         leastIncrement(setup_.increment, modal_.unit);
}

// The finishing contour: blocks ns..nf of the current program, evaluated now.
lathe::Contour Executor::readContour(int ns, int nf, std::vector<double>& feeds,
                                     uint32_t& lastBlock) {
  const Frame& f = frames_.back();
  const Program& prog = *f.prog;
  wholeProgram(prog);
  int32_t first = prog.findLabel(ns, f.pc);
  if (first < 0) throw AlarmError(AlarmId::CycleSequenceNotFound, fmt::format("P{}", ns));
  int32_t last = prog.findLabel(nf, static_cast<uint32_t>(first));
  if (last < first) throw AlarmError(AlarmId::CycleSequenceNotFound, fmt::format("Q{}", nf));
  lathe::Contour c;
  c.start = latheHere();
  lathe::Pt at = c.start;
  int motion = -1;
  int comp = modal_.g[7];  // G40/G41/G42 may also be given inside the shape
  double feed = modal_.feed;
  double u = unitNm(modal_.unit);
  const Block* saved = block_;
  std::vector<ContourCorner> corners;  // ,C/,R of the shape blocks
  int32_t angleSecond = -1;            // the block after an angle-only ,A block
  for (int32_t k = first; k <= last; ++k) {
    const Block& b = prog.blocks[static_cast<size_t>(k)];
    if (b.kind == BlockKind::Empty) continue;
    block_ = &b;  // an alarm below names this shape block, not the one before it
    if (b.kind != BlockKind::Nc)
      throw AlarmError(AlarmId::CycleUnavailableCommand, "only NC blocks between P and Q");
    Words w;
    gatherWords(b, w);
    for (int g = 0; g < w.ng; ++g) {
      int code = w.g[static_cast<size_t>(g)];
      if (code == 0 || code == 10 || code == 20 || code == 30)
        motion = code;
      else if (code == 400 || code == 410 || code == 420)
        comp = code;
      else if (code != 400 && code != 410 && code != 420 && code != 40)
        throw AlarmError(AlarmId::CycleUnavailableCommand,
                         fmt::format("G{} between P and Q", code / 10));
    }
    // A subprogram call or return cannot be part of the shape: the control reads ns..nf as
    // one stretch of the current program (0i-F/30i: PS0066).
    for (int m = 0; m < w.nm; ++m) {
      int32_t code = w.m[static_cast<size_t>(m)];
      if (code == 98 || code == 99)
        throw AlarmError(AlarmId::CycleUnavailableCommand,
                         fmt::format("M{} between P and Q", code));
    }
    if (k == first) {
      if (motion != 0 && motion != 10) throw AlarmError(AlarmId::ShapeFirstBlockNotG00G01);
      c.nsNamesZ = w.has('Z') || w.has('W');
    }
    if (w.has('F')) feed = w.value('F');
    if (!w.any("XZUWRIK") && !w.hasCommaA) continue;
    lathe::ContourSeg s;
    s.blockIndex = k;
    s.comp = comp;
    if (w.hasCommaA) shapeDirectDrawing(prog, k, last, w, at, motion, angleSecond);
    s.end = latheTarget(w, at);
    // Parameter 3403#5 (CIR) = 0: an arc with neither R nor I/K is a line to its end point.
    bool arc = (motion == 20 || motion == 30) && (w.any("RIK") || setup_.bit("3403#5"));
    if (arc) {
      s.kind = motion == 20 ? lathe::SegKind::ArcCw : lathe::SegKind::ArcCcw;
      if (!w.any("RIK")) throw AlarmError(AlarmId::NoRadiusOrCenter, "G02/G03 between P and Q");
      if (w.has('R')) {
        double r = latheLength(w, 'R', false);
        double du = s.end.z - at.z, dv = s.end.x - at.x, d = std::hypot(du, dv);
        double h = std::sqrt(std::max(0.0, r * r - d * d / 4.0));
        double side = (motion == 20 ? -1.0 : 1.0) * (r < 0 ? -1.0 : 1.0);
        s.center = {(at.x + s.end.x) / 2.0 + side * h * du / d,
                    (at.z + s.end.z) / 2.0 - side * h * dv / d};
      } else {
        s.center = {at.x + (w.has('I') ? latheLength(w, 'I', false) : 0.0),
                    at.z + (w.has('K') ? latheLength(w, 'K', false) : 0.0)};
      }
    } else {
      s.kind = motion == 0 ? lathe::SegKind::Rapid : lathe::SegKind::Line;
    }
    (void)u;
    if (w.hasCorner())
      corners.push_back(
          {c.segs.size(), w.hasCommaC,
           static_cast<double>(lengthNm(w.commaValue, w.commaPoint, 2)) / unitNm(modal_.unit), &b});
    c.segs.push_back(s);
    feeds.push_back(feed);
    at = s.end;
  }
  block_ = saved;
  applyContourCorners(c, feeds, corners);
  lastBlock = static_cast<uint32_t>(last);
  return c;
}

void Executor::runLathePlan(const std::vector<lathe::Move>& moves,
                            const std::vector<double>* contourFeeds, double lead) {
  double u = unitNm(modal_.unit);
  double feedBefore = modal_.feed;
  bool perRevBefore = modal_.feedPerRev;
  int planeBefore = modal_.plane;
  modal_.plane = 18;
  for (const lathe::Move& m : moves) {
    std::array<int64_t, kMaxAxes> target{};
    for (size_t k = 0; k < kMaxAxes; ++k) target[k] = machine_[k] - offset_[k];
    target[0] = static_cast<int64_t>(std::llround(m.end.x * u));
    target[2] = static_cast<int64_t>(std::llround(m.end.z * u));
    if (contourFeeds && m.contourIndex >= 0 &&
        static_cast<size_t>(m.contourIndex) < contourFeeds->size())
      modal_.feed = (*contourFeeds)[static_cast<size_t>(m.contourIndex)];
    else
      modal_.feed = feedBefore;
    if (m.thread) {
      // Threading is synchronised with the spindle: F is the lead per revolution.
      modal_.feed = lead;
      modal_.feedPerRev = true;
    }
    threadMove_ = m.thread;
    // Tool-nose radius compensation: the trace keeps the programmed point and the nose centre.
    AxisArray prog{}, nose{};
    if (m.compensated) {
      for (int k = 0; k < kMaxAxes; ++k)
        prog[static_cast<size_t>(k)] = toProgramUnits(target[static_cast<size_t>(k)], k, true);
      nose = prog;
      prog[0] = 2.0 * m.programmed.x;
      prog[2] = m.programmed.z;
      nose[0] = 2.0 * m.nose.x;
      nose[2] = m.nose.z;
      programmedEnd_ = &prog;
      noseEnd_ = &nose;
    }
    switch (m.kind) {
      case lathe::SegKind::Rapid:
        moveTo(target, MoveMode::Rapid, 0);
        break;
      case lathe::SegKind::Line:
        moveTo(target, MoveMode::Linear, 0);
        break;
      case lathe::SegKind::ArcCw:
      case lathe::SegKind::ArcCcw:
        arcWithCenter(target, m.center.z * u, m.center.x * u, m.kind == lathe::SegKind::ArcCw);
        break;
    }
    threadMove_ = false;
    programmedEnd_ = nullptr;
    noseEnd_ = nullptr;
    modal_.feedPerRev = perRevBefore;
  }
  modal_.feed = feedBefore;
  modal_.plane = planeBefore;
}

// The first-block data of G71-G76 start as the control's parameters; a first block then
// replaces them, as it rewrites the parameters on a real control. Lengths are in the
// machine's unit (setup machine.units), radius values. An unset parameter keeps ncvm's
// fallback (docs/setup-format.md, "Fanuc parameters ncvm reads").
void Executor::loadLatheCycleParams() {
  LatheCycleState& s = latheCyc_;
  s.paramsLoaded = true;
  // Machine unit -> current program unit.
  double k = setup_.initialUnit == modal_.unit       ? 1.0
             : setup_.initialUnit == InputUnit::Inch ? 25.4
                                                     : 1.0 / 25.4;
  auto len = [&](const char* key, double fallback) { return setup_.param(key, fallback / k) * k; };
  auto count = [&](const char* key, int fallback) {
    return static_cast<int>(std::llround(setup_.param(key, fallback)));
  };
  s.depth = len("5132", 1.0);
  s.retract = len("5133", 0.5);
  s.reliefX = len("5135", 0.0);
  s.reliefZ = len("5136", 0.0);
  s.divisions = count("5137", 1);
  s.peckRetract = len("5139", 0.0);
  s.thread.minCut = len("5140", 0.0);
  s.thread.finishAllowance = len("5141", 0.0);
  s.thread.finishPasses = count("5142", 1);
  s.thread.angle = count("5143", 60);
  s.thread.chamfer = count("5130", 10);
}

// Returns true when the block ran (or set up) a lathe cycle.
bool Executor::latheCycle(const Words& w, int kind) {
  if (!latheCyc_.paramsLoaded) loadLatheCycleParams();
  auto plan = [&](auto&& make) {
    try {
      return make();
    } catch (const lathe::CycleError& e) {
      throw AlarmError(e.id, e.what());
    }
  };
  const lathe::Pt here = latheHere();
  switch (kind) {
    case kTurn:
    case kFace:
    case kThread: {
      if (!w.any("XZUW")) return false;  // modal single cycle: only blocks with a position run
      if (latheCyc_.singleKind != kind) {
        // A new single cycle starts from fresh modal data.
        latheCyc_.singleKind = kind;
        latheCyc_.haveEnd = false;
        latheCyc_.taper = 0;
      }
      if (w.has('R')) latheCyc_.taper = latheLength(w, 'R', false);
      // X, Z and R stay in force from block to block: "X45." alone repeats the cycle to the
      // same Z at the new diameter.
      lathe::Pt end = latheTarget(w, here);
      if (latheCyc_.haveEnd) {
        if (!w.has('X') && !w.has('U')) end.x = latheCyc_.lastEnd.x;
        if (!w.has('Z') && !w.has('W')) end.z = latheCyc_.lastEnd.z;
      }
      latheCyc_.lastEnd = end;
      latheCyc_.haveEnd = true;
      std::vector<lathe::Move> moves;
      if (kind == kThread) {
        // Parameter 5130, also rewritten by the r of a G76 first block (0.1 lead units).
        double chamfer = latheCyc_.thread.chamfer / 10.0 * modal_.feed;
        moves = plan([&] { return lathe::threadCycle(here, end, latheCyc_.taper, chamfer); });
        runLathePlan(moves, nullptr, modal_.feed);
      } else {
        moves = plan([&] { return lathe::singleCycle(here, end, latheCyc_.taper, kind == kFace); });
        if (tnrcActive()) moves = tnrcSingleCycle(here, moves, kind == kFace);
        runLathePlan(moves, nullptr, 0);
      }
      return true;
    }
    case kRoughTurn:
    case kRoughFace:
    case kPattern:
    case kFinish: {
      bool second = w.has('P') && w.has('Q');
      // P without Q (or Q without P) names half a shape program.
      if (w.has('P') != w.has('Q')) throw AlarmError(AlarmId::CycleAddressPQNotFound);
      if (!second) {
        // First block: depth and retract (G71 U R, G72 W R) or relief and divisions (G73).
        if (kind == kRoughTurn && w.has('U')) latheCyc_.depth = latheLength(w, 'U', false);
        if (kind == kRoughFace && w.has('W')) latheCyc_.depth = latheLength(w, 'W', false);
        if ((kind == kRoughTurn || kind == kRoughFace) && w.has('R'))
          latheCyc_.retract = latheLength(w, 'R', false);
        if (kind == kPattern) {
          if (w.has('U')) latheCyc_.reliefX = latheLength(w, 'U', false);
          if (w.has('W')) latheCyc_.reliefZ = latheLength(w, 'W', false);
          if (w.has('R')) latheCyc_.divisions = static_cast<int>(std::llround(w.value('R')));
        }
        if (kind == kFinish) throw AlarmError(AlarmId::CycleAddressPQNotFound);
        return true;
      }
      std::vector<double> feeds;
      uint32_t last = 0;
      lathe::Contour c = readContour(static_cast<int>(std::llround(w.value('P'))),
                                     static_cast<int>(std::llround(w.value('Q'))), feeds, last);
      double allowX = w.has('U') ? latheLength(w, 'U', true) : 0.0;
      double allowZ = w.has('W') ? latheLength(w, 'W', false) : 0.0;
      std::vector<lathe::Move> moves;
      // Under G41/G42 every one of these cycles works on the compensated shape.
      bool tnrc = modal_.g[7] != 400;
      for (const lathe::ContourSeg& s : c.segs) tnrc |= s.comp >= 0 && s.comp != 400;
      tnrc = tnrc && lathe_ && tnrcRadius() != 0;
      if (tnrc) c = tnrcContour(c, feeds);
      if (kind == kFinish) {
        moves = plan([&] { return lathe::finishing(c); });
        if (tnrc) {
          crc::P2 tv = tnrcTipVector(tnrcRadius());
          for (lathe::Move& m : moves) {
            m.compensated = true;
            if (m.contourIndex >= 0 &&
                static_cast<size_t>(m.contourIndex) < tnrcProgrammed_.size()) {
              m.programmed = tnrcProgrammed_[static_cast<size_t>(m.contourIndex)].first;
              m.nose = tnrcProgrammed_[static_cast<size_t>(m.contourIndex)].second;
            } else {
              m.programmed = c.start;  // the return to the start point
              m.nose = {m.end.x - tv.v, m.end.z - tv.u};
            }
          }
        }
        runLathePlan(moves, &feeds, 0);
        return true;  // G70 continues with the next block
      }
      if (kind == kPattern) {
        lathe::PatternParams p{latheCyc_.reliefX, latheCyc_.reliefZ, allowX, allowZ,
                               latheCyc_.divisions};
        moves = plan([&] { return lathe::patternRepeating(c, p); });
      } else {
        lathe::RoughParams p{latheCyc_.depth, latheCyc_.retract, allowX, allowZ,
                             leastIncrement(setup_.increment, modal_.unit)};
        if (p.depth <= 0) throw AlarmError(AlarmId::CycleIllegalCommand, "depth of cut");
        moves = plan([&] {
          return kind == kRoughTurn ? lathe::roughTurning(c, p) : lathe::roughFacing(c, p);
        });
      }
      runLathePlan(moves, nullptr, 0);
      // G71-G73 consume the contour: the program goes on after its last block (the caller
      // still advances past the current block, so stop one short).
      frames_.back().pc = last;
      return true;
    }
    case kFacePeck:
    case kGroove: {
      if (!w.any("XZUW")) {
        if (w.has('R')) latheCyc_.peckRetract = latheLength(w, 'R', false);
        return true;
      }
      lathe::PeckParams p;
      p.retract = latheCyc_.peckRetract;
      p.step = w.has('P') ? latheIncrements(w, 'P') : 0.0;
      p.peck = w.has('Q') ? latheIncrements(w, 'Q') : 0.0;
      p.relief = w.has('R') ? latheLength(w, 'R', false) : 0.0;
      lathe::Pt end = latheTarget(w, here);
      auto moves = plan([&] { return lathe::peckCycle(here, end, p, kind == kGroove); });
      runLathePlan(moves, nullptr, 0);
      return true;
    }
    case kMultiThread: {
      if (!w.any("XZUW")) {
        if (w.has('P')) {
          auto pm = std::llround(w.value('P'));
          latheCyc_.thread.finishPasses = static_cast<int>(pm / 10000);
          latheCyc_.thread.chamfer = static_cast<int>(pm / 100 % 100);
          latheCyc_.thread.angle = static_cast<int>(pm % 100);
        }
        if (w.has('Q')) latheCyc_.thread.minCut = latheIncrements(w, 'Q');
        if (w.has('R')) latheCyc_.thread.finishAllowance = latheLength(w, 'R', false);
        return true;
      }
      lathe::ThreadParams p = latheCyc_.thread;
      p.taper = w.has('R') ? latheLength(w, 'R', false) : 0.0;
      p.height = w.has('P') ? latheIncrements(w, 'P') : 0.0;
      p.firstCut = w.has('Q') ? latheIncrements(w, 'Q') : 0.0;
      p.lead = modal_.feed;
      lathe::Pt end = latheTarget(w, here);
      auto moves = plan([&] { return lathe::multipleThreading(here, end, p); });
      runLathePlan(moves, nullptr, p.lead);
      return true;
    }
    default:
      return false;
  }
}

}  // namespace ncvm
