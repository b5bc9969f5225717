// Lathe tool-nose radius compensation (fanuc-reference E.2). The program describes the path
// of the imaginary tip; the cutter compensation engine (src/motion/cutter_comp) places the
// nose centre at R from it in the ZX plane, and the tool moves its imaginary tip, which is
// the nose centre plus the tip vector of the imaginary tip direction (0-9). Plain blocks go
// through crc_exec.cpp with these helpers; the lathe cycles are handled here: G90/G94 offset
// their own legs, G71-G73 rough the compensated shape, G70 follows it.
#include <fmt/format.h>

#include <cmath>

#include "exec/executor.hpp"
#include "exec/words.hpp"
#include "motion/crc_geom.hpp"
#include "motion/tip_direction.hpp"

namespace ncvm {

namespace {
double unitOf(InputUnit u) {
  return u == InputUnit::Inch ? 25.4e6 : 1e6;
}

crc::P2 toPlane(const lathe::Pt& p) {
  return {p.z, p.x};
}
lathe::Pt fromPlane(const crc::P2& p) {
  return {p.v, p.u};
}
lathe::Pt plus(const lathe::Pt& a, const lathe::Pt& b) {
  return {a.x + b.x, a.z + b.z};
}
lathe::Pt minus(const lathe::Pt& a, const lathe::Pt& b) {
  return {a.x - b.x, a.z - b.z};
}

// Where the imaginary tip lies relative to the nose centre, as (X radius, Z) in units of R
// (X+ up, Z+ right): 2 6 1 / 7 0 5 / 3 8 4.
lathe::Pt tipDirection(int tip) {
  const lathe::TipSigns t = lathe::tipSigns(tip);
  return {static_cast<double>(t.x), static_cast<double>(t.z)};
}

// Intersection of the lines p + t d and q + s e; nullopt when parallel.
std::optional<lathe::Pt> meet(const lathe::Pt& p, const lathe::Pt& d, const lathe::Pt& q,
                              const lathe::Pt& e) {
  double den = d.x * e.z - d.z * e.x;
  if (std::abs(den) < 1e-12) return std::nullopt;
  double t = ((q.x - p.x) * e.z - (q.z - p.z) * e.x) / den;
  return lathe::Pt{p.x + t * d.x, p.z + t * d.z};
}
}  // namespace

// The T code's offset number (oo of Tttoo): its row gives the wear R and the tip.
int Executor::tnrcOffsetRow() const {
  int row = latheWearNumber(modal_.tool);
  return row > 0 && row < kToolRows ? row : 0;
}

// Nose radius in program units: geometry R of the tool's geometry row plus wear R of the
// offset row, like X and Z (applyToolShift).
double Executor::tnrcRadius() const {
  int row = tnrcOffsetRow();
  if (row == 0) return 0.0;
  int geo = latheGeometryNumber(modal_.tool);
  if (geo <= 0 || geo >= kToolRows) geo = 0;
  int64_t r = mem_.tools[static_cast<size_t>(geo)].geometry[kFieldRorD] +
              mem_.tools[static_cast<size_t>(row)].wear[kFieldRorD];
  return toProgramUnits(r, 2, false);
}

// Tip minus nose centre in the plane (u = Z, v = X radius), program units. Only G18 has an
// imaginary tip layout; other planes compensate the nose centre.
crc::P2 Executor::tnrcTipVector(double radius) const {
  if (modal_.plane != 18) return {};
  lathe::Pt d = tipDirection(mem_.tools[static_cast<size_t>(tnrcOffsetRow())].tip);
  return {d.z * radius, d.x * radius};
}

AxisArray Executor::tnrcNoseEnd(const std::array<int64_t, kMaxAxes>& tipWork,
                                const crc::P2& tip) const {
  double unit = unitOf(modal_.unit);
  std::array<int64_t, kMaxAxes> nose = tipWork;
  nose[2] -= static_cast<int64_t>(std::llround(tip.u * unit));
  nose[0] -= static_cast<int64_t>(std::llround(tip.v * unit));
  AxisArray out{};
  for (int k = 0; k < kMaxAxes; ++k)
    out[static_cast<size_t>(k)] = toProgramUnits(nose[static_cast<size_t>(k)], k, true);
  return out;
}

bool Executor::tnrcActive() const {
  return lathe_ && modal_.g[7] != 400 && tnrcRadius() != 0;
}

// A lathe cycle block in compensation mode: the cycle starts from its programmed start
// point, so the held block ends there with no vector (fanuc-decisions.md).
void Executor::tnrcBeforeCycle(int, const Words&) {
  if (crcBusy()) {
    try {
      if (crc_) crc_->suspend();
    } catch (const crc::CrcError& e) {
      throw AlarmError(e.id, e.what());
    }
    releasePending(true);
  }
  // The cycle's own moves are not held: they are compensated here, not by the lookahead.
  deferring_ = crcBusy();
}

// G90 (face false) / G94 (face true) under G41/G42: each of the four legs is offset by R to
// the side away from the material the cycle removes (the start point's side of the
// finished surface and of the shoulder), regardless of G41/G42; the nose centre runs
// through the intersections of the offset legs and the tool moves its imaginary tip.
std::vector<lathe::Move> Executor::tnrcSingleCycle(const lathe::Pt& a,
                                                   const std::vector<lathe::Move>& plain,
                                                   bool face) {
  double r = tnrcRadius();
  if (plain.size() < 3) return plain;
  const lathe::Pt end = latheCyc_.lastEnd;
  double taper = latheCyc_.taper;
  lathe::Pt b = face ? lathe::Pt{a.x, end.z + taper} : lathe::Pt{end.x + taper, a.z};
  lathe::Pt c = end;
  lathe::Pt d = face ? lathe::Pt{end.x, a.z} : lathe::Pt{a.x, end.z};
  auto sgn = [](double v) { return v > 0 ? 1.0 : v < 0 ? -1.0 : 0.0; };
  lathe::Pt side{sgn(a.x - c.x), sgn(a.z - c.z)};
  const lathe::Pt corner[4] = {a, b, c, d};
  lathe::Pt off[4], dir[4];
  for (int i = 0; i < 4; ++i) {
    const lathe::Pt& p = corner[i];
    const lathe::Pt& q = corner[(i + 1) % 4];
    lathe::Pt v = minus(q, p);
    double len = std::hypot(v.x, v.z);
    if (len < 1e-9)
      v = i % 2 == 0 ? (face ? lathe::Pt{0, 1} : lathe::Pt{1, 0})
                     : (face ? lathe::Pt{1, 0} : lathe::Pt{0, 1});
    else
      v = {v.x / len, v.z / len};
    lathe::Pt n{-v.z, v.x};
    if (n.x * side.x + n.z * side.z < 0) n = {-n.x, -n.z};
    dir[i] = v;
    off[i] = {p.x + r * n.x, p.z + r * n.z};
  }
  crc::P2 tv = tnrcTipVector(r);
  lathe::Pt tip{tv.v, tv.u};
  // Nose centre at the end of leg i = intersection of offset legs i and i+1.
  lathe::Pt nose[4];
  for (int i = 0; i < 4; ++i) {
    auto m = meet(off[i], dir[i], off[(i + 1) % 4], dir[(i + 1) % 4]);
    if (!m) throw AlarmError(AlarmId::NoIntersectionCrc, "G90/G94 legs do not meet");
    nose[i] = *m;
  }
  // The cutting legs must keep their direction: a cut shallower than the nose allows
  // would run backwards (16i alarm 040 for an interfering single cycle).
  for (int i = 1; i <= 2; ++i) {
    lathe::Pt got = minus(nose[i], nose[i - 1]);
    lathe::Pt want = minus(corner[(i + 1) % 4], corner[i]);
    if (got.x * want.x + got.z * want.z < 0)
      throw AlarmError(AlarmId::InterferenceInCrc, face ? "G94 cut too small for the nose radius"
                                                        : "G90 cut too small for the nose radius");
  }
  std::vector<lathe::Move> out;
  const lathe::SegKind kinds[4] = {lathe::SegKind::Rapid, lathe::SegKind::Line,
                                   lathe::SegKind::Line, lathe::SegKind::Rapid};
  for (int i = 0; i < 4; ++i) {
    lathe::Move m;
    m.kind = kinds[i];
    m.compensated = true;
    m.programmed = corner[(i + 1) % 4];
    // The last leg returns the tip to the start point, where the next pass begins.
    m.end = i == 3 ? a : plus(nose[i], tip);
    m.nose = i == 3 ? minus(a, tip) : nose[i];
    out.push_back(m);
  }
  return out;
}

// G70-G73 under G41/G42: the finishing shape A -> ns .. nf -> A as the compensated path of
// the imaginary tip: start-up on the ns block, the corners of offset mode, and the return
// to A as the cancel. Each block uses the G40/G41/G42 in effect for it: the cycle block's,
// or one given inside the shape. `feeds` (one per contour block) is rebuilt for the pieces.
lathe::Contour Executor::tnrcContour(const lathe::Contour& c, std::vector<double>& feeds) {
  crc::Options o;
  o.startupTypeB = setup_.bit("5003#0");
  std::vector<crc::OutSeg> got;
  crc::Compensator comp(o, [&](const crc::OutSeg& s) { got.push_back(s); });
  double r = tnrcRadius();
  crc::P2 at = toPlane(c.start);
  int mode = modal_.g[7];
  const int n = static_cast<int>(c.segs.size());
  try {
    for (int i = 0; i < n; ++i) {
      const lathe::ContourSeg& s = c.segs[static_cast<size_t>(i)];
      crc::InSeg in;
      in.kind = s.kind == lathe::SegKind::ArcCw    ? crc::Kind::Cw
                : s.kind == lathe::SegKind::ArcCcw ? crc::Kind::Ccw
                                                   : crc::Kind::Line;
      in.start = at;
      in.end = toPlane(s.end);
      in.center = toPlane(s.center);
      in.rapid = s.kind == lathe::SegKind::Rapid;
      if (s.comp >= 0) mode = s.comp;  // pieces added to the shape (,C/,R) keep the mode
      in.side = mode == 410 ? crc::Side::Left : mode == 420 ? crc::Side::Right : crc::Side::Off;
      in.radius = r;
      in.tag = i;
      comp.push(in);
      at = in.end;
    }
    crc::InSeg back;
    back.start = at;
    back.end = toPlane(c.start);
    back.rapid = true;
    back.side = crc::Side::Off;
    back.radius = r;
    back.tag = n;
    comp.push(back);
    comp.flush();
  } catch (const crc::CrcError& e) {
    throw AlarmError(e.id, e.what());
  }
  crc::P2 tv = tnrcTipVector(r);
  lathe::Contour out;
  out.start = c.start;
  out.nsNamesZ = c.nsNamesZ;
  std::vector<double> newFeeds;
  tnrcProgrammed_.clear();
  for (const crc::OutSeg& s : got) {
    if (s.tag >= n) break;  // the return to A: G70 adds it, G71-G73 end there anyway
    const lathe::ContourSeg& from = c.segs[static_cast<size_t>(s.tag)];
    crc::P2 shift = s.vectorAtEnd ? tv : crc::P2{};
    lathe::ContourSeg seg;
    seg.kind = s.kind == crc::Kind::Cw    ? lathe::SegKind::ArcCw
               : s.kind == crc::Kind::Ccw ? lathe::SegKind::ArcCcw
               : s.rapid                  ? lathe::SegKind::Rapid
                                          : lathe::SegKind::Line;
    seg.end = fromPlane({s.end.u + shift.u, s.end.v + shift.v});
    seg.center = fromPlane({s.center.u + tv.u, s.center.v + tv.v});
    seg.blockIndex = from.blockIndex;
    out.segs.push_back(seg);
    newFeeds.push_back(feeds[static_cast<size_t>(s.tag)]);
    tnrcProgrammed_.push_back({from.end, fromPlane(s.end)});
  }
  feeds = std::move(newFeeds);
  return out;
}

}  // namespace ncvm
