#include "sim/lathe_insert.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "motion/tip_direction.hpp"

namespace ncvm::lsim {

Pt tipDirection(int tip) {
  // The unit vector towards the imaginary tip (motion/tip_direction.hpp; docs/fanuc-decisions.md).
  const lathe::TipSigns t = lathe::tipSigns(tip);
  const double n = std::hypot(t.x, t.z);
  if (n == 0) return {0, 0};
  return {t.x / n, t.z / n};
}

namespace {

// A drill (or an end mill used on the lathe centre line): point at the programmed point,
// body along +Z.
std::vector<Pt> drillOutline(const ToolSpec& t, double defaultLength) {
  double R = t.diameter / 2;
  double length = t.fluteLength > 0 ? t.fluteLength : defaultLength;
  double pointDepth = t.type == "drill" && t.pointAngle > 0 && t.pointAngle < 180
                          ? R / std::tan(t.pointAngle * std::numbers::pi / 360)
                          : 0.0;
  std::vector<Pt> out{{-R, pointDepth}, {0, 0}, {R, pointDepth}, {R, length}, {-R, length}};
  if (pointDepth == 0) out = {{-R, 0}, {R, 0}, {R, length}, {-R, length}};
  return out;
}

}  // namespace

std::vector<Pt> toolOutline(const ToolSpec& t, double chordError, double defaultEdge) {
  if (t.type != "insert" && t.diameter > 0) return drillOutline(t, defaultEdge);
  double r = t.noseRadius;
  Pt dir = tipDirection(t.tip);
  // Tip 0/9: the program drives the nose centre; the insert body is taken as an OD tool's (tip 3).
  Pt body = dir.r == 0 && dir.z == 0 ? Pt{std::numbers::sqrt2 / 2, std::numbers::sqrt2 / 2}
                                     : Pt{-dir.r, -dir.z};
  // The imaginary tip is where the tangents parallel to the axes meet: for a diagonal
  // tip r * (+-1, +-1) from the centre, for an axial one r along it.
  Pt centre{0, 0};
  if (dir.r != 0 || dir.z != 0) {
    double sr = dir.r == 0 ? 0 : (dir.r > 0 ? 1 : -1), sz = dir.z == 0 ? 0 : (dir.z > 0 ? 1 : -1);
    centre = {-r * sr, -r * sz};
  }
  double edge = t.edgeLength > 0 ? t.edgeLength : defaultEdge;
  double half = t.insertAngle * std::numbers::pi / 360;
  double b = std::atan2(body.r, body.z);  // angle of the body direction in the (z, r) plane
  // The edges leave the nose at b -+ half; each is tangent to the circle where the radius
  // is perpendicular to it, on the side away from the body.
  double e1 = b - half, e2 = b + half;
  double n1 = e1 - std::numbers::pi / 2, n2 = e2 + std::numbers::pi / 2;
  std::vector<Pt> out;
  auto at = [&](double a, double rad) {
    return Pt{centre.r + rad * std::sin(a), centre.z + rad * std::cos(a)};
  };
  if (r > 0) {
    // The arc facing the tip runs from n2 on round to n1 + 2 pi (180 - angle degrees).
    double span = n1 + 2 * std::numbers::pi - n2;
    double step = 2 * std::acos(std::max(-1.0, 1 - chordError / r));
    int n = std::max(2, static_cast<int>(std::ceil(span / step)));
    // Vertices a little outside the circle, chord middles a little inside: the polygon
    // errs by about chordError / 2 either way instead of always leaving material.
    double rad = r * (1 + 1 / std::cos(span / n / 2)) / 2;
    out.push_back(at(n2, r));
    for (int k = 1; k < n; ++k) out.push_back(at(n2 + span * k / n, rad));
    out.push_back(at(n1, r));
  } else {
    out.push_back(centre);
  }
  Pt t1 = at(n1, r), t2 = at(n2, r);
  out.push_back({t1.r + edge * std::sin(e1), t1.z + edge * std::cos(e1)});
  out.push_back({t2.r + edge * std::sin(e2), t2.z + edge * std::cos(e2)});
  return out;
}

std::vector<Pt> holderOutline(const ToolSpec& t, double defaultEdge) {
  if (t.holderDiameter <= 0 || t.holderLength <= 0) return {};
  if (t.type != "insert" && t.diameter > 0) return {};
  const lathe::TipSigns s = lathe::tipSigns(t.tip);
  double r = t.noseRadius;
  Pt centre{-r * s.x, -r * s.z};  // the nose centre, opposite the imaginary tip
  // The shank's axis: +X for OD tools, along Z away from the tip for boring bars.
  Pt axis = s.x > 0 ? Pt{0, s.z > 0 ? -1.0 : 1.0} : Pt{1, 0};
  if (s.x > 0 && s.z == 0) axis = {0, 1};
  Pt side{axis.z, axis.r};  // perpendicular to the axis (swap: the axes are orthogonal)
  double edge = t.edgeLength > 0 ? t.edgeLength : defaultEdge;
  double w = t.holderDiameter / 2, from = edge, to = edge + t.holderLength;
  auto at = [&](double along, double across) {
    return Pt{centre.r + axis.r * along + side.r * across,
              centre.z + axis.z * along + side.z * across};
  };
  return {at(from, -w), at(to, -w), at(to, w), at(from, w)};
}

std::vector<Pt> sweptHull(const std::vector<Pt>& outline, Pt a, Pt b) {
  std::vector<Pt> pts;
  pts.reserve(outline.size() * 2);
  for (const Pt& p : outline) pts.push_back({p.r + a.r, p.z + a.z});
  if (a.r != b.r || a.z != b.z)
    for (const Pt& p : outline) pts.push_back({p.r + b.r, p.z + b.z});
  // Andrew's monotone chain in (z, r).
  std::sort(pts.begin(), pts.end(),
            [](const Pt& p, const Pt& q) { return p.z < q.z || (p.z == q.z && p.r < q.r); });
  auto cross = [](const Pt& o, const Pt& p, const Pt& q) {
    return (p.z - o.z) * (q.r - o.r) - (p.r - o.r) * (q.z - o.z);
  };
  std::vector<Pt> hull(pts.size() * 2);
  size_t k = 0;
  for (size_t i = 0; i < pts.size(); ++i) {
    while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[i]) <= 0) --k;
    hull[k++] = pts[i];
  }
  for (size_t i = pts.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[i - 1]) <= 0) --k;
    hull[k++] = pts[i - 1];
  }
  hull.resize(k > 1 ? k - 1 : k);
  return hull;
}

void supportsAcross(const std::vector<Pt>& hull, Pt d, size_t& lo, size_t& hi) {
  lo = hi = 0;
  double slo = 0, shi = 0;
  for (size_t k = 0; k < hull.size(); ++k) {
    double s = d.z * hull[k].r - d.r * hull[k].z;
    if (k == 0 || s < slo) lo = k, slo = s;
    if (k == 0 || s > shi) hi = k, shi = s;
  }
}

void sweepPath(const std::vector<Pt>& hull, const std::vector<Pt>& path, size_t lo, size_t hi,
               std::vector<Pt>& out) {
  out.clear();
  const size_t n = hull.size();
  if (n < 2 || path.empty()) return;
  auto at = [&](size_t k, const Pt& p) { out.push_back({hull[k].r + p.r, hull[k].z + p.z}); };
  // Counter-clockwise: the back chain (hi .. lo) at the first point, the lo side along the
  // path, the front chain (lo .. hi) at the last point, the hi side back along the path.
  for (size_t k = hi;; k = (k + 1) % n) {
    at(k, path.front());
    if (k == lo) break;
  }
  for (size_t j = 1; j + 1 < path.size(); ++j) at(lo, path[j]);
  for (size_t k = lo;; k = (k + 1) % n) {
    at(k, path.back());
    if (k == hi) break;
  }
  for (size_t j = path.size() - 1; j-- > 1;) at(hi, path[j]);
}

void sweepConvex(const std::vector<Pt>& hull, Pt a, Pt b, std::vector<Pt>& out) {
  const Pt d{b.r - a.r, b.z - a.z};
  if ((d.r == 0 && d.z == 0) || hull.size() < 2) {
    out.clear();
    for (const Pt& p : hull) out.push_back({p.r + a.r, p.z + a.z});
    return;
  }
  size_t lo = 0, hi = 0;
  supportsAcross(hull, d, lo, hi);
  sweepPath(hull, {a, b}, lo, hi, out);
}

}  // namespace ncvm::lsim
