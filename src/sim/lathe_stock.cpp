#include "sim/lathe_stock.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <numbers>
#include <sstream>

#include "sim/lathe_probe.hpp"

namespace ncvm {

using ClipperLib::cInt;
using lsim::Pt;

namespace {

cInt toInt(double v) {
  return static_cast<cInt>(std::llround(v * LatheStock::kScale));
}

void toPath(const std::vector<Pt>& pts, ClipperLib::Path& p) {
  p.clear();
  for (const Pt& q : pts) p.push_back({toInt(q.z), toInt(q.r)});  // X = z, Y = r
}

// Lowest r of a polygon over the z range [a, b] (its lower envelope there): a tile whose
// material stays below it cannot be touched, the common case behind the nose.
double lowestOver(const ClipperLib::Path& poly, cInt a, cInt b) {
  double best = std::numeric_limits<double>::infinity();
  for (size_t k = 0; k < poly.size(); ++k) {
    const auto& p = poly[k];
    const auto& q = poly[(k + 1) % poly.size()];
    cInt lo = std::max(a, std::min(p.X, q.X)), hi = std::min(b, std::max(p.X, q.X));
    if (lo > hi) continue;
    if (p.X == q.X) {
      best = std::min(best, static_cast<double>(std::min(p.Y, q.Y)));
      continue;
    }
    auto at = [&](cInt z) {
      return static_cast<double>(p.Y) + static_cast<double>(z - p.X) /
                                            static_cast<double>(q.X - p.X) *
                                            static_cast<double>(q.Y - p.Y);
    };
    best = std::min({best, at(lo), at(hi)});
  }
  return best;
}

// The part of the convex polygon `in` inside the box [z0, z1] x [r0, r1] (Sutherland-Hodgman,
// one axis-parallel half-plane at a time), into `out`. The box is the tile's material bounds
// grown by a margin, so the part cut away holds no material and the vertices made on the box
// sides (rounded to whole units) only move edges outside the material: the difference with
// the tile is the same, with a clip polygon of a third of the vertices (the edges and the far
// side of the nose are gone), which is what Clipper's cost grows with.
void clipToBox(const ClipperLib::Path& in, cInt z0, cInt z1, cInt r0, cInt r1,
               ClipperLib::Path& out, ClipperLib::Path& scratch) {
  out = in;
  auto pass = [&](auto inside, auto cross) {
    scratch.clear();
    for (size_t k = 0; k < out.size(); ++k) {
      const ClipperLib::IntPoint& p = out[k];
      const ClipperLib::IntPoint& q = out[(k + 1) % out.size()];
      bool pin = inside(p), qin = inside(q);
      if (pin) scratch.push_back(p);
      if (pin != qin) scratch.push_back(cross(p, q));
    }
    out.swap(scratch);
  };
  auto onZ = [](cInt z) {
    return [z](const ClipperLib::IntPoint& p, const ClipperLib::IntPoint& q) {
      double t = static_cast<double>(z - p.X) / static_cast<double>(q.X - p.X);
      return ClipperLib::IntPoint{
          z, p.Y + static_cast<cInt>(std::llround(t * static_cast<double>(q.Y - p.Y)))};
    };
  };
  auto onR = [](cInt r) {
    return [r](const ClipperLib::IntPoint& p, const ClipperLib::IntPoint& q) {
      double t = static_cast<double>(r - p.Y) / static_cast<double>(q.Y - p.Y);
      return ClipperLib::IntPoint{
          p.X + static_cast<cInt>(std::llround(t * static_cast<double>(q.X - p.X))), r};
    };
  };
  pass([z0](const ClipperLib::IntPoint& p) { return p.X >= z0; }, onZ(z0));
  if (out.size() >= 3) pass([z1](const ClipperLib::IntPoint& p) { return p.X <= z1; }, onZ(z1));
  if (out.size() >= 3) pass([r0](const ClipperLib::IntPoint& p) { return p.Y >= r0; }, onR(r0));
  if (out.size() >= 3) pass([r1](const ClipperLib::IntPoint& p) { return p.Y <= r1; }, onR(r1));
  if (out.size() < 3) out.clear();
}

double pathsArea(const ClipperLib::Paths& ps) {
  double a = 0;
  for (const auto& p : ps) a += ClipperLib::Area(p);
  return a / (LatheStock::kScale * LatheStock::kScale);
}

}  // namespace

std::unique_ptr<StockModel> makeLatheStock(const Setup& setup) {
  return std::make_unique<LatheStock>(setup);
}

LatheStock::LatheStock(const Setup& setup) : setup_(setup), frame_(setup, true) {
  const StockSpec& st = setup.stock;
  auto need = [&](bool ok, const std::string& what) {
    if (!ok) throw SetupError("stock: a lathe stock needs " + what, "stock", st.line);
  };
  need(st.diameter > 0, "a diameter");
  need(st.length > 0, "a length");
  need(st.boreDiameter < st.diameter, "a bore_diameter below its diameter");
  unit_ = setup.initialUnit == InputUnit::Inch ? 1 / 25.4 : 1.0;
  tol_ = setup.target.tolerance > 0 ? setup.target.tolerance : (unit_ < 1 ? 0.0004 : 0.01);
  chord_ = tol_ / 20;
  rIn_ = st.boreDiameter / 2;
  rOut_ = st.diameter / 2;
  zFront_ = st.frontZ;
  zBack_ = st.frontZ - st.length;
  // Tiles about 1 mm wide (at most 4096 of them): a short move touches one or two.
  double w = std::max(unit_ * 0.5, st.length / 4096);
  size_t n = static_cast<size_t>(std::ceil(st.length / w));
  tileW_ = toInt(w);
  tileZ0_ = toInt(zBack_);
  tiles_.resize(n);
  for (size_t k = 0; k < n; ++k) {
    cInt z0 = tileZ0_ + static_cast<cInt>(k) * tileW_;
    cInt z1 = std::min(z0 + tileW_, toInt(zFront_));
    tiles_[k].paths = {
        {{z0, toInt(rIn_)}, {z1, toInt(rIn_)}, {z1, toInt(rOut_)}, {z0, toInt(rOut_)}}};
    refreshBounds(tiles_[k]);
    tiles_[k].area = pathsArea(tiles_[k].paths);
  }
  selectTool(ToolSpec{"insert"});
  if (setup.target.present) {
    if (!setup.target.polyline.empty())
      loadTargetFile();
    else if (setup.target.fromN < 0)
      throw SetupError("target: a lathe target needs blocks = \"N..N\" or polyline = FILE",
                       "target", setup.target.line);
    else
      targetSource_ = fmt::format("blocks N{}..N{}", setup.target.fromN, setup.target.toN);
  }
}

void LatheStock::refreshBounds(Tile& t) {
  t.empty = true;
  cInt zmin = 0, zmax = 0, rmin = 0, rmax = 0;
  for (const auto& p : t.paths)
    for (const auto& q : p) {
      if (t.empty) zmin = zmax = q.X, rmin = rmax = q.Y, t.empty = false;
      zmin = std::min(zmin, q.X), zmax = std::max(zmax, q.X);
      rmin = std::min(rmin, q.Y), rmax = std::max(rmax, q.Y);
    }
  t.zmin = zmin, t.zmax = zmax, t.rmin = rmin, t.rmax = rmax;
}

void LatheStock::selectTool(const ToolSpec& tool) {
  // The outline's hull once, so each move's sweep is a linear-time Minkowski sum.
  outline_ = lsim::sweptHull(lsim::toolOutline(tool, chord_, 10 * unit_), {}, {});
  holder_ = lsim::holderOutline(tool, 10 * unit_);
  if (!holder_.empty()) holder_ = lsim::sweptHull(holder_, {}, {});
}

void LatheStock::onTool(const ToolEvent& e) {
  flush();  // the pending moves were made with the previous tool
  // The physical tool: [tools.T] by the turret number (T0101 -> 1) or by the whole T word
  // (101); without one, the nose radius and tip of the offset row of the same number.
  ToolSpec spec{"insert"};
  std::string source = "none";
  if (const ToolSpec* ts = physicalTool(setup_, e.tool)) {
    spec = *ts;
    source = "tools";
  }
  if (source == "none") {
    auto it = setup_.toolOffsets.find(e.tool);
    if (it != setup_.toolOffsets.end()) {
      spec.noseRadius = it->second.geometry[kFieldRorD];
      spec.tip = it->second.tip;
      source = "offsets";
    }
  }
  if (source == "none")
    notes_.push_back(fmt::format(
        "T{}: no [tools] entry and no offset row: simulated as a sharp tip-0 insert", e.tool));
  selectTool(spec);
  toolKnown_ = true;
  // A touch probe touches (G31, probe.use_stock); it does not cut. Its ball as G31 sees it
  // (exec/probe.cpp): probe.ball_diameter for probe.tool (or every tool), else its diameter.
  cuts_ = spec.type != "probe";
  const ProbeSpec& pr = setup_.probe;
  probeRadius_ = (pr.tool < 0 || pr.tool == e.tool) && pr.ballDiameter > 0 ? pr.ballDiameter / 2
                                                                           : spec.diameter / 2;
  noseNow_ = cuts_ ? spec.noseRadius : 0;
  if (cuts_) noseMax_ = std::max(noseMax_, spec.noseRadius);
  if (!cuts_)
    notes_.push_back(fmt::format("T{}: a probe does not cut: its moves remove nothing", e.tool));
  tools_.push_back({{"t", e.tool},
                    {"type", spec.type},
                    {"nose_radius", spec.noseRadius},
                    {"tip", spec.tip},
                    {"diameter", spec.diameter},
                    {"source", source}});
}

double LatheStock::area() {
  flush();
  double a = 0;
  for (const auto& t : tiles_) a += pathsArea(t.paths);
  return a;
}

std::optional<double> LatheStock::probeContact(const Vec3& a, const Vec3& b, double r) {
  return ProfileProbe(profile(), kScale).firstContact(a, b, r);
}

ClipperLib::Paths LatheStock::profile() {
  flush();
  ClipperLib::Clipper c;
  for (const auto& t : tiles_) c.AddPaths(t.paths, ClipperLib::ptSubject, true);
  ClipperLib::Paths out;
  c.Execute(ClipperLib::ctUnion, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

double LatheStock::apply(const ClipperLib::Path& poly, bool& reached) {
  if (poly.size() < 3 || tiles_.empty()) return 0;
  cInt zlo = poly.front().X, zhi = zlo, rlo = poly.front().Y, rhi = rlo;
  for (const auto& q : poly) {
    zlo = std::min(zlo, q.X), zhi = std::max(zhi, q.X);
    rlo = std::min(rlo, q.Y), rhi = std::max(rhi, q.Y);
  }
  double removed = 0;
  if (zhi >= tileZ0_) {
    long first = std::max<long>(0, static_cast<long>((zlo - tileZ0_) / tileW_));
    long last = std::min<long>(static_cast<long>(tiles_.size()) - 1,
                               static_cast<long>((zhi - tileZ0_) / tileW_));
    for (long k = first; k <= last; ++k) {
      Tile& t = tiles_[static_cast<size_t>(k)];
      // Bounds first, then the sweep's lower envelope against the tile's highest material.
      if (t.empty || t.zmax <= zlo || t.zmin >= zhi || t.rmax <= rlo || t.rmin >= rhi) continue;
      clipToBox(poly, t.zmin - kMargin, t.zmax + kMargin, t.rmin - kMargin, t.rmax + kMargin,
                boxed_, scratch_);
      if (boxed_.empty() || static_cast<double>(t.rmax) <= lowestOver(boxed_, t.zmin, t.zmax))
        continue;
      reached = true;
      clipper_.Clear();
      clipper_.AddPaths(t.paths, ClipperLib::ptSubject, true);
      clipper_.AddPath(boxed_, ClipperLib::ptClip, true);
      clipper_.Execute(ClipperLib::ctDifference, result_, ClipperLib::pftNonZero,
                       ClipperLib::pftNonZero);
      double after = pathsArea(result_);
      if (t.area - after <= 0) continue;  // touched the bounds only
      removed += t.area - after;
      t.paths.swap(result_);
      t.area = after;
      refreshBounds(t);
    }
  }
  removed_ += removed;
  return removed;
}

double LatheStock::applyWithMirror(const ClipperLib::Path& poly, bool* reached) {
  bool hit = false;
  double removed = apply(poly, hit);
  // Past the spindle axis the tool cuts the other side of the part: the mirror image.
  if (std::any_of(poly.begin(), poly.end(),
                  [](const ClipperLib::IntPoint& q) { return q.Y < 0; })) {
    mirror_.assign(poly.rbegin(), poly.rend());
    for (auto& q : mirror_) q.Y = -q.Y;
    removed += apply(mirror_, hit);
  }
  if (reached) *reached = hit;
  return removed;
}

double LatheStock::cutLine(Pt a, Pt b, bool* reached) {
  flush();
  lsim::sweepConvex(outline_, a, b, swept_);
  toPath(swept_, poly_);
  return applyWithMirror(poly_, reached);
}

// Can the polygon touch some tile's material? Bounds, then its lower envelope against the
// tile's highest material.
bool LatheStock::touches(const ClipperLib::Path& poly) const {
  if (poly.size() < 3 || tiles_.empty()) return false;
  cInt zlo = poly.front().X, zhi = zlo, rlo = poly.front().Y, rhi = rlo;
  for (const auto& q : poly) {
    zlo = std::min(zlo, q.X), zhi = std::max(zhi, q.X);
    rlo = std::min(rlo, q.Y), rhi = std::max(rhi, q.Y);
  }
  if (zhi < tileZ0_) return false;
  long first = std::max<long>(0, static_cast<long>((zlo - tileZ0_) / tileW_));
  long last = std::min<long>(static_cast<long>(tiles_.size()) - 1,
                             static_cast<long>((zhi - tileZ0_) / tileW_));
  for (long k = first; k <= last; ++k) {
    const Tile& t = tiles_[static_cast<size_t>(k)];
    if (t.empty || t.zmax <= zlo || t.zmin >= zhi || t.rmax <= rlo || t.rmin >= rhi) continue;
    if (static_cast<double>(t.rmax) > lowestOver(poly, t.zmin, t.zmax)) return true;
  }
  return false;
}

double LatheStock::overlap(const ClipperLib::Path& poly) {
  if (!touches(poly)) return 0;
  cInt zlo = poly.front().X, zhi = zlo;
  for (const auto& q : poly) zlo = std::min(zlo, q.X), zhi = std::max(zhi, q.X);
  long first = std::max<long>(0, static_cast<long>((zlo - tileZ0_) / tileW_));
  long last = std::min<long>(static_cast<long>(tiles_.size()) - 1,
                             static_cast<long>((zhi - tileZ0_) / tileW_));
  double a = 0;
  for (long k = first; k <= last; ++k) {
    const Tile& t = tiles_[static_cast<size_t>(k)];
    if (t.empty) continue;
    clipper_.Clear();
    clipper_.AddPaths(t.paths, ClipperLib::ptSubject, true);
    clipper_.AddPath(poly, ClipperLib::ptClip, true);
    clipper_.Execute(ClipperLib::ctIntersection, result_, ClipperLib::pftNonZero,
                     ClipperLib::pftNonZero);
    a += pathsArea(result_);
  }
  return a;
}

bool LatheStock::queueLine(Pt a, Pt b) {
  const Pt d{b.r - a.r, b.z - a.z};
  if (d.r == 0 && d.z == 0) {  // the tool standing still: its outline alone
    bool hit = false;
    cutLine(a, b, &hit);
    return hit;
  }
  size_t lo = 0, hi = 0;
  lsim::supportsAcross(outline_, d, lo, hi);
  bool joins = !pending_.empty() && pending_.size() <= kMaxPending && lo == pendLo_ &&
               hi == pendHi_ && pending_.back().r == a.r && pending_.back().z == a.z;
  if (!joins) {
    flush();
    pending_ = {a};
    pendLo_ = lo, pendHi_ = hi;
  }
  pending_.push_back(b);
  // The move's own sweep against the stock as it stands (before the pending moves).
  lsim::sweepPath(outline_, {a, b}, lo, hi, swept_);
  toPath(swept_, poly_);
  if (touches(poly_)) return true;
  if (!std::any_of(poly_.begin(), poly_.end(),
                   [](const ClipperLib::IntPoint& q) { return q.Y < 0; }))
    return false;
  mirror_.assign(poly_.rbegin(), poly_.rend());
  for (auto& q : mirror_) q.Y = -q.Y;
  return touches(mirror_);
}

double LatheStock::flush() {
  if (pending_.size() < 2) {
    pending_.clear();
    return 0;
  }
  lsim::sweepPath(outline_, pending_, pendLo_, pendHi_, swept_);
  pending_.clear();
  toPath(swept_, poly_);
  return applyWithMirror(poly_, nullptr);
}

void LatheStock::cutPath(const std::vector<Pt>& pts, const MoveEvent& e) {
  cutMove(pts, e);
  if (holder_.size() < 3) return;
  // The holder against the stock the move left (the insert cuts ahead of it): every move,
  // feed or rapid. Material inside its swept area is a contact; grazing as for rapids.
  flush();
  double contact = 0;
  for (size_t k = 1; k < pts.size(); ++k) {
    lsim::sweepConvex(holder_, pts[k - 1], pts[k], swept_);
    toPath(swept_, poly_);
    contact += overlap(poly_);
  }
  if (contact > tol_ * tol_)
    collisions_.push_back({{"kind", "holder"},
                           {"program", e.at.programName ? *e.at.programName : std::string()},
                           {"line", e.at.line},
                           {"n", e.at.n},
                           {"amount", contact}});
}

void LatheStock::cutMove(const std::vector<Pt>& pts, const MoveEvent& e) {
  if (e.mode != MoveMode::Rapid) {
    bool reached = false;
    for (size_t k = 1; k < pts.size(); ++k) {
      reached |= queueLine(pts[k - 1], pts[k]);
    }
    if (reached) ++cuttingMoves_;
    return;
  }
  double removed = 0;
  for (size_t k = 1; k < pts.size(); ++k) removed += cutLine(pts[k - 1], pts[k]);
  if (removed > 0) ++cuttingMoves_;
  // A rapid that removes material is a crash. Rounding of the polygon can graze the
  // profile the previous feed move left: far below any real contact, so it does not count.
  double grazing = tol_ * tol_;
  if (e.mode == MoveMode::Rapid && removed > grazing) {
    collisions_.push_back({{"kind", "rapid"},
                           {"program", e.at.programName ? *e.at.programName : std::string()},
                           {"line", e.at.line},
                           {"n", e.at.n},
                           {"amount", removed}});
  }
}

void LatheStock::onMove(const MoveEvent& work) {
  ++moves_;
  frame_.move(work);
  const MoveEvent& e = frame_.place(work, placed_);
  auto rz = [](const AxisArray& a) { return Pt{a[0] / 2, a[2]}; };
  std::vector<Pt> pts{rz(e.start)};
  if (e.arc) {
    // In the (z, r) plane (Z right, X up) G02 runs clockwise.
    Pt c{e.center[0] / 2, e.center[2]};
    Pt s = rz(e.start), f = rz(e.end);
    double a0 = std::atan2(s.r - c.r, s.z - c.z), a1 = std::atan2(f.r - c.r, f.z - c.z);
    double R0 = std::hypot(s.r - c.r, s.z - c.z), R1 = std::hypot(f.r - c.r, f.z - c.z);
    double sweep = a1 - a0;
    bool cw = e.mode == MoveMode::Cw;
    if (cw && sweep >= 0) sweep -= 2 * std::numbers::pi;
    if (!cw && sweep <= 0) sweep += 2 * std::numbers::pi;
    double R = std::max(R0, R1);
    double step = R > chord_ ? 2 * std::acos(1 - chord_ / R) : std::numbers::pi / 2;
    int n = std::max(1, static_cast<int>(std::ceil(std::fabs(sweep) / step)));
    for (int k = 1; k < n; ++k) {
      double t = static_cast<double>(k) / n, a = a0 + sweep * t, rad = R0 + (R1 - R0) * t;
      pts.push_back({c.r + rad * std::sin(a), c.z + rad * std::cos(a)});
    }
  } else {
    for (int k = 0; k < e.pathPoints; ++k) pts.push_back(rz(e.path[static_cast<size_t>(k)]));
  }
  pts.push_back(rz(e.end));
  if (!toolKnown_ && moves_ == 1 && !setup_.tools.empty())
    notes_.push_back("moves before the first T use a sharp insert");
  if (cuts_) {
    cutPath(pts, e);
  } else if (!e.skip) {
    checkProbeMove(e, pts);
  }
  if (setup_.target.present && setup_.target.fromN >= 0) captureTarget(e, pts);
}

// As on the mill (sim/mill_stock.cpp): the amount is how far the move went on past the first
// contact. Touching is not a crash: after a G31 the ball sits on the surface (its latch
// rounded to the increment) and may slide along it, so the test ball is the tolerance
// smaller (for a point probe: it must go the tolerance deep). A move that starts in the
// material was reported when it went in, or was left there by a G31.
void LatheStock::checkProbeMove(const MoveEvent& e, const std::vector<Pt>& pts) {
  // The path in 3D (radius, Y, Z); Y runs linearly along it (lathe moves leave it alone).
  const double y0 = e.start[1], y1 = e.end[1];
  std::vector<Vec3> path;
  path.reserve(pts.size());
  for (size_t k = 0; k < pts.size(); ++k) {
    double u = pts.size() > 1 ? static_cast<double>(k) / static_cast<double>(pts.size() - 1) : 0;
    path.push_back({pts[k].r, y0 + (y1 - y0) * u, pts[k].z});
  }
  auto length = [&](size_t k) {
    const Vec3 &a = path[k - 1], &b = path[k];
    return std::hypot(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  };
  const double r = probeRadius_ - tol_;
  std::optional<ProfileProbe> probe;
  for (size_t k = 1; k < path.size(); ++k) {
    const double len = length(k);
    if (len <= 0) continue;
    const bool first = !probe;
    if (first) probe.emplace(profile(), kScale);
    std::optional<double> t = probe->firstContact(path[k - 1], path[k], r);
    if (!t) continue;
    if (first && *t == 0) return;
    double amount = (1 - *t) * len;
    for (size_t j = k + 1; j < path.size(); ++j) amount += length(j);
    if (amount <= 0) return;  // reaches the tolerance depth just at its end
    collisions_.push_back({{"kind", "probe"},
                           {"program", e.at.programName ? *e.at.programName : std::string()},
                           {"line", e.at.line},
                           {"n", e.at.n},
                           {"amount", amount}});
    return;
  }
}

void LatheStock::captureTarget(const MoveEvent& e, const std::vector<Pt>& pts) {
  // The programmed contour: under nose-radius compensation the move ends at the
  // compensated point and programmedEnd is the programmed one; an arc keeps its centre.
  Pt progEnd = e.compensated ? Pt{e.programmedEnd[0] / 2, e.programmedEnd[2]} : pts.back();
  Pt progStart = havePos_ ? programmed_ : pts.front();
  programmed_ = progEnd;
  havePos_ = true;
  if (captured_) return;
  const TargetSpec& tg = setup_.target;
  bool inRange = e.at.n >= tg.fromN && e.at.n <= tg.toN &&
                 (!targetProgram_ || targetProgram_ == e.at.programName);
  // Blocks without N inside the range belong to it.
  if (capturing_ && e.at.n < 0 && targetProgram_ == e.at.programName) inRange = true;
  if (!inRange) {
    if (capturing_) captured_ = true;
    return;
  }
  capturing_ = true;
  if (noseTarget_ < 0) noseTarget_ = noseNow_;
  targetProgram_ = e.at.programName;
  if (e.mode == MoveMode::Rapid) return;
  if (!e.compensated) {
    for (size_t k = 1; k < pts.size(); ++k) target_.push_back({pts[k - 1], pts[k], e.at.n});
    return;
  }
  if (!e.arc) {
    target_.push_back({progStart, progEnd, e.at.n});
    return;
  }
  // Cutter compensation keeps the arc's centre. Nose-radius compensation moves the
  // imaginary tip on the nose-centre arc shifted by the tip vector, and the centre with it:
  // the programmed arc is concentric with the nose-centre arc.
  Pt c{e.center[0] / 2, e.center[2]};
  if (e.nose) c = {c.r + (e.noseEnd[0] - e.end[0]) / 2, c.z + e.noseEnd[2] - e.end[2]};
  double a0 = std::atan2(progStart.r - c.r, progStart.z - c.z),
         a1 = std::atan2(progEnd.r - c.r, progEnd.z - c.z);
  double R = std::hypot(progEnd.r - c.r, progEnd.z - c.z), sweep = a1 - a0;
  if (e.mode == MoveMode::Cw && sweep >= 0) sweep -= 2 * std::numbers::pi;
  if (e.mode == MoveMode::Ccw && sweep <= 0) sweep += 2 * std::numbers::pi;
  int n = std::max(1, static_cast<int>(std::ceil(std::fabs(sweep) * R / tol_)));
  Pt prev = progStart;
  for (int k = 1; k <= n; ++k) {
    double a = a0 + sweep * k / n;
    Pt p = k == n ? progEnd : Pt{c.r + R * std::sin(a), c.z + R * std::cos(a)};
    target_.push_back({prev, p, e.at.n});
    prev = p;
  }
}

void LatheStock::loadTargetFile() {
  const std::string& path = setup_.target.polyline;
  std::ifstream in(path);
  if (!in)
    throw SetupError("target.polyline: cannot read " + path, "target.polyline", setup_.target.line);
  std::string line;
  int lineNo = 0;
  std::vector<Pt> pts;
  while (std::getline(in, line)) {
    ++lineNo;
    auto hash = line.find('#');
    if (hash != std::string::npos) line.resize(hash);
    std::replace(line.begin(), line.end(), ',', ' ');
    std::istringstream ss(line);
    double x = 0, z = 0;
    if (!(ss >> x)) continue;  // blank or comment line
    std::string rest;
    if (!(ss >> z) || (ss >> rest))
      throw SetupError(
          fmt::format("target.polyline: {}:{}: expected X (diameter) and Z", path, lineNo),
          "target.polyline", setup_.target.line);
    pts.push_back({x / 2, z});
  }
  if (pts.size() < 2)
    throw SetupError("target.polyline: " + path + " needs at least two points", "target.polyline",
                     setup_.target.line);
  for (size_t k = 1; k < pts.size(); ++k) target_.push_back({pts[k - 1], pts[k], -1});
  captured_ = true;
  targetSource_ = "polyline " + path;
}

}  // namespace ncvm
