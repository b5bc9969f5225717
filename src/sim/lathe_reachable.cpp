#include "sim/lathe_reachable.hpp"

#include <cmath>

namespace ncvm {

using ClipperLib::cInt;
using lsim::Pt;

namespace {

double areaOf(const ClipperLib::Paths& ps, double scale) {
  double a = 0;
  for (const auto& p : ps) a += ClipperLib::Area(p);
  return a / (scale * scale);
}

ClipperLib::Paths boolean(ClipperLib::ClipType op, const ClipperLib::Paths& a,
                          const ClipperLib::Paths& b) {
  ClipperLib::Clipper c;
  c.AddPaths(a, ClipperLib::ptSubject, true);
  c.AddPaths(b, ClipperLib::ptClip, true);
  ClipperLib::Paths out;
  c.Execute(op, out, ClipperLib::pftNonZero, ClipperLib::pftNonZero);
  return out;
}

ClipperLib::Paths offset(const ClipperLib::Paths& in, double delta, ClipperLib::JoinType join,
                         ClipperLib::EndType end, double arcTolerance) {
  ClipperLib::ClipperOffset o(2.0, arcTolerance);
  o.AddPaths(in, join, end);
  ClipperLib::Paths out;
  o.Execute(out, delta);
  return out;
}

}  // namespace

ReachablePart reachablePart(const std::vector<Pt>& contour, const ClipperLib::Paths& stock,
                            const ClipperLib::Path& raw, double noseRadius, double arcTolerance,
                            double minCornerArea, double scale) {
  ReachablePart out;
  if (contour.size() < 2 || raw.size() < 3) return out;
  // The contour, both ends prolonged along their direction far past the raw stock, so it
  // cuts the raw rectangle in two (a G70 contour usually starts and ends outside or on it).
  cInt zlo = raw[0].X, zhi = zlo, rlo = raw[0].Y, rhi = rlo;
  for (const auto& q : raw)
    zlo = std::min(zlo, q.X), zhi = std::max(zhi, q.X), rlo = std::min(rlo, q.Y),
    rhi = std::max(rhi, q.Y);
  double reach = 2.0 * static_cast<double>((zhi - zlo) + (rhi - rlo)) / scale + 1.0;
  auto prolong = [&](Pt from, Pt to) {  // from `to` onwards, away from `from`
    double dr = to.r - from.r, dz = to.z - from.z, L = std::hypot(dr, dz);
    return Pt{to.r + dr / L * reach, to.z + dz / L * reach};
  };
  std::vector<Pt> pts;
  for (const Pt& p : contour)
    if (pts.empty() || std::hypot(p.r - pts.back().r, p.z - pts.back().z) > 1.0 / scale)
      pts.push_back(p);
  if (pts.size() < 2) return out;
  ClipperLib::Path line;
  auto put = [&](Pt p) {
    line.push_back({static_cast<cInt>(std::llround(p.z * scale)),
                    static_cast<cInt>(std::llround(p.r * scale))});
  };
  put(prolong(pts[1], pts[0]));
  for (const Pt& p : pts) put(p);
  put(prolong(pts[pts.size() - 2], pts.back()));
  // The raw rectangle less a thin band along the contour falls apart into pieces on either
  // side; the pieces that kept most of their material after the run are the part.
  constexpr double kBand = 4;  // integer units either side of the contour
  ClipperLib::Paths band =
      offset({line}, kBand, ClipperLib::jtMiter, ClipperLib::etOpenButt, arcTolerance);
  ClipperLib::Paths pieces = boolean(ClipperLib::ctDifference, {raw}, band);
  ClipperLib::Paths part;
  for (const auto& piece : pieces) {
    if (!ClipperLib::Orientation(piece)) continue;  // a hole (none for a simple contour)
    double a = areaOf({piece}, scale);
    if (a <= 0) continue;
    double kept = areaOf(boolean(ClipperLib::ctIntersection, {piece}, stock), scale);
    if (kept > 0.5 * a) part.push_back(piece);
  }
  if (part.empty() || part.size() == pieces.size()) return out;  // no air side or no part side
  // The sharp part (the band given back) and its closing by the nose disc: grow by r, shrink
  // by r, round joins: concave corners fill with a fillet of r, the rest comes back as it was.
  ClipperLib::Paths sharp =
      offset(part, kBand, ClipperLib::jtMiter, ClipperLib::etClosedPolygon, arcTolerance);
  double r = noseRadius * scale;
  ClipperLib::Paths grown =
      offset(part, r + kBand, ClipperLib::jtRound, ClipperLib::etClosedPolygon, arcTolerance);
  ClipperLib::Paths closed =
      offset(grown, -r, ClipperLib::jtRound, ClipperLib::etClosedPolygon, arcTolerance);
  out.part = boolean(ClipperLib::ctIntersection, closed, {raw});
  for (const auto& piece : boolean(ClipperLib::ctDifference, out.part, sharp)) {
    double a = areaOf({piece}, scale);
    out.unreachableArea += a;
    if (a > minCornerArea) ++out.corners;
  }
  out.found = true;
  return out;
}

}  // namespace ncvm
