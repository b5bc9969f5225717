#include "sim/mill_sweep.hpp"

#include <cmath>
#include <limits>

// The inner loops are written as straight-line float code over one row so the compiler
// vectorises them; the per-move entry points are compiled twice (AVX2 and baseline x86-64)
// and picked at load time. No FMA: both versions give the same heights.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && \
    !defined(__SANITIZE_ADDRESS__)
#define NCVM_CLONES __attribute__((target_clones("avx2", "default")))
#else
#define NCVM_CLONES
#endif
#define NCVM_INLINE __attribute__((always_inline)) inline

namespace ncvm {
namespace {

constexpr float kNone = 3.0e38f;  // "the tool does not reach": finite, for -ffinite-math-only

constexpr double kKeepAll = -1e300;  // keepFrom for "keep every cell" (no infinities here)

// The rows of the stadium of radius r around the segment (0,0)-(dx,dy) in coordinates local
// to its start: the discs at both ends and the band between them. Set up once per move so
// each row costs two square roots and a few products.
class StadiumRows {
 public:
  StadiumRows(double dx, double dy, double r, double keepFrom)
      : dx_(dx), dy_(dy), r_(r), r2_(r * r), keepFrom_(keepFrom) {
    len_ = std::sqrt(dx * dx + dy * dy);
    if (len_ > 0) {
      ux_ = dx / len_;
      uy_ = dy / len_;
      invUx_ = std::abs(ux_) > kTiny ? 1 / ux_ : 0;
      invUy_ = std::abs(uy_) > kTiny ? 1 / uy_ : 0;
    }
  }

  // The local x interval where the row at local y `ry` meets the stadium. The stadium is
  // convex, so the union of its parts is one interval. Only the part whose distance along
  // the segment (from its start, in the direction of travel) is at least keepFrom is kept:
  // behind that line the tool at the start point is lowest, and that was cut already.
  NCVM_INLINE bool span(double ry, double& lo, double& hi) const {
    lo = 1e300;
    hi = -lo;
    disc(ry, 0, 0, lo, hi);
    disc(ry, dx_, dy_, lo, hi);
    if (len_ > 0) {
      // Band: along = rx ux + ry uy in [0, len], across = ry ux - rx uy in [-r, r].
      double bl = -1e300, bh = 1e300;
      if (clip(ux_, invUx_, ry * uy_, 0, len_, bl, bh) &&
          clip(-uy_, -invUy_, ry * ux_, -r_, r_, bl, bh)) {
        lo = std::min(lo, bl);
        hi = std::max(hi, bh);
      }
      if (keepFrom_ > kKeepAll) {
        double m = ry * uy_;
        if (ux_ > kTiny)
          lo = std::max(lo, (keepFrom_ - m) * invUx_);
        else if (ux_ < -kTiny)
          hi = std::min(hi, (keepFrom_ - m) * invUx_);
        else if (m < keepFrom_)
          return false;
      }
    }
    return lo <= hi;
  }

 private:
  static constexpr double kTiny = 1e-12;
  NCVM_INLINE void disc(double ry, double cx, double cy, double& lo, double& hi) const {
    double v = r2_ - (ry - cy) * (ry - cy);
    if (v < 0) return;
    double w = std::sqrt(v);
    lo = std::min(lo, cx - w);
    hi = std::max(hi, cx + w);
  }
  // Clips `lo <= k*x + m <= hi` (inv = 1/k, or 0 where k is tiny) into [xlo, xhi].
  NCVM_INLINE static bool clip(double k, double inv, double m, double lo, double hi, double& xlo,
                               double& xhi) {
    if (inv == 0) return std::abs(k) <= kTiny && m >= lo && m <= hi;
    double p = (lo - m) * inv, q = (hi - m) * inv;
    if (p > q) std::swap(p, q);
    xlo = std::max(xlo, p);
    xhi = std::min(xhi, q);
    return xlo <= xhi;
  }
  double dx_, dy_, r_, r2_, keepFrom_;
  double len_ = 0, ux_ = 0, uy_ = 0, invUx_ = 0, invUy_ = 0;
};

// Cell range [lo, hi) of n cells of size 1/inv from `origin` whose centres lie within [a, b]
// (HeightField::columnsWithin, inlined into the kernel with a product for the division).
NCVM_INLINE void cellsWithin(double a, double b, double origin, double inv, int n, int& lo,
                             int& hi) {
  double l = std::ceil((a - origin) * inv - 0.5);
  double h = std::floor((b - origin) * inv - 0.5) + 1;
  lo = static_cast<int>(std::clamp(l, 0.0, static_cast<double>(n)));
  hi = static_cast<int>(std::clamp(h, 0.0, static_cast<double>(n)));
}

// Runs `cell(rx, ry)` (local coordinates relative to the segment start; returns the tool's
// lower envelope there, kNone where it does not reach) over the stadium's cells.
template <SweepMode M, class CellFn>
NCVM_INLINE float sweepStadium(HeightField& f, double ax, double ay, double dx, double dy, double r,
                               double keepFrom, Stripe stripe, CellFn cell) {
  int jlo, jhi;
  f.rowsWithin(std::min(ay, ay + dy) - r, std::max(ay, ay + dy) + r, jlo, jhi);
  float pen = 0;
  const StadiumRows rows(dx, dy, r, keepFrom);
  const auto step = static_cast<float>(f.cell());
  const double inv = 1 / f.cell(), x0 = f.x0() - ax;
  for (int j = jlo; j < jhi; ++j) {
    if (!stripe.owns(j)) continue;
    double ry = f.cellY(j) - ay, lo, hi;
    if (!rows.span(ry, lo, hi)) continue;
    int ilo, ihi;
    cellsWithin(lo, hi, x0, inv, f.nx(), ilo, ihi);
    if (ilo >= ihi) continue;
    float* z = f.row(j) + ilo;
    const auto rx0 = static_cast<float>(f.cellX(ilo) - ax);
    const auto ryf = static_cast<float>(ry);
    const int n = ihi - ilo;
    for (int k = 0; k < n; ++k) {
      float rx = rx0 + static_cast<float>(k) * step;
      float old = z[k];
      float nz = std::min(old, cell(rx, ryf));
      pen = std::max(pen, old - nz);
      if constexpr (M == SweepMode::Cut) z[k] = nz;
    }
  }
  return pen;
}

// Lower surface height above the tip, from the squared radial distance d2 <= R^2.
struct FlatProfile {
  NCVM_INLINE float operator()(float) const { return 0.0f; }
};
struct BallProfile {
  float r, r2;
  NCVM_INLINE float operator()(float d2) const { return r - std::sqrt(std::max(r2 - d2, 0.0f)); }
};
struct BullProfile {
  float flat, c, c2;
  NCVM_INLINE float operator()(float d2) const {
    float u = std::max(std::sqrt(d2) - flat, 0.0f);
    return c - std::sqrt(std::max(c2 - u * u, 0.0f));
  }
};
struct DrillProfile {
  float slope;
  NCVM_INLINE float operator()(float d2) const { return std::sqrt(d2) * slope; }
};

// Horizontal move (or a point): the envelope is z + h(distance to the segment in XY).
template <SweepMode M, class Profile>
NCVM_INLINE float horizontal(HeightField& f, double radius, const Point3& a, double dx, double dy,
                             double keepFrom, Stripe stripe, Profile h) {
  const double l2 = dx * dx + dy * dy;
  const auto inv = static_cast<float>(l2 > 0 ? 1.0 / l2 : 0.0);
  const auto fdx = static_cast<float>(dx), fdy = static_cast<float>(dy);
  const auto r2 = static_cast<float>(radius * radius);
  const auto z0 = static_cast<float>(a[2]);
  return sweepStadium<M>(f, a[0], a[1], dx, dy, radius, keepFrom, stripe, [=](float rx, float ry) {
    float t = std::clamp((rx * fdx + ry * fdy) * inv, 0.0f, 1.0f);
    float ex = rx - t * fdx, ey = ry - t * fdy;
    float d2 = ex * ex + ey * ey;
    return d2 <= r2 ? z0 + h(d2) : kNone;
  });
}

// Ball on a sloped move: the lower surface of the capsule of ball centres. Where the
// nearest point lies inside the segment it is the cylinder around it (a quadratic in z),
// otherwise one of the end spheres; the envelope is the lowest valid one. StartCut: the
// sphere at the start was cut already (the move continues an earlier one), so it cannot
// lower any cell and is left out.
template <SweepMode M, bool StartCut>
NCVM_INLINE float ballSloped(HeightField& f, double radius, const Point3& a, const Point3& d,
                             double keepFrom, Stripe stripe) {
  const double lxy2 = d[0] * d[0] + d[1] * d[1], l2 = lxy2 + d[2] * d[2];
  const auto fdx = static_cast<float>(d[0]), fdy = static_cast<float>(d[1]);
  const auto fdz = static_cast<float>(d[2]);
  const auto fl2 = static_cast<float>(l2), inv = static_cast<float>(1.0 / l2);
  const auto invxy = static_cast<float>(1.0 / lxy2);
  const auto r = static_cast<float>(radius), r2 = r * r;
  const auto za = static_cast<float>(a[2] + radius), zb = static_cast<float>(a[2] + d[2] + radius);
  return sweepStadium<M>(
      f, a[0], a[1], d[0], d[1], radius, keepFrom, stripe, [=](float rx, float ry) {
        float s = rx * rx + ry * ry;
        float p = rx * fdx + ry * fdy;
        float bx = rx - fdx, by = ry - fdy;
        float sb = bx * bx + by * by;
        float zA = kNone;
        if constexpr (!StartCut) zA = s <= r2 ? za - std::sqrt(std::max(r2 - s, 0.0f)) : kNone;
        float zB = sb <= r2 ? zb - std::sqrt(std::max(r2 - sb, 0.0f)) : kNone;
        // Cylinder: |w|^2 - (w.d)^2 / l2 = r^2 for w = (rx, ry, wz), lower root.
        float q = p * p * fdz * fdz - (fdx * fdx + fdy * fdy) * (s * fl2 - p * p - r2 * fl2);
        float wz = (p * fdz - std::sqrt(std::max(q, 0.0f))) * invxy;
        float t = (p + wz * fdz) * inv;
        float zC = (q >= 0 && t >= 0 && t <= 1) ? za + wz : kNone;
        return std::min(zC, std::min(zA, zB));
      });
}

// Flat end mill on a sloped move: the bottom disc is lowest at one end of the interval of
// positions where it covers the cell.
template <SweepMode M>
NCVM_INLINE float flatSloped(HeightField& f, double radius, const Point3& a, const Point3& d,
                             double keepFrom, Stripe stripe) {
  const double lxy2 = d[0] * d[0] + d[1] * d[1];
  const auto fdx = static_cast<float>(d[0]), fdy = static_cast<float>(d[1]);
  const auto fdz = static_cast<float>(d[2]);
  const auto fl = static_cast<float>(lxy2), invxy = static_cast<float>(1.0 / lxy2);
  const auto r2 = static_cast<float>(radius * radius);
  const auto z0 = static_cast<float>(a[2]);
  const bool rising = d[2] > 0;
  return sweepStadium<M>(f, a[0], a[1], d[0], d[1], radius, keepFrom, stripe,
                         [=](float rx, float ry) {
                           float s = rx * rx + ry * ry;
                           float p = rx * fdx + ry * fdy;
                           float disc = p * p - fl * (s - r2);
                           float root = std::sqrt(std::max(disc, 0.0f));
                           float t1 = (p - root) * invxy, t2 = (p + root) * invxy;
                           float t = rising ? std::max(t1, 0.0f) : std::min(t2, 1.0f);
                           bool hit = disc >= 0 && t1 <= 1 && t2 >= 0;
                           return hit ? z0 + t * fdz : kNone;
                         });
}

// Any profile on a sloped move: z(t) + h(|q - p(t)|) is convex in t (h convex and rising,
// the distance convex), so bisection on its slope finds the minimum. Scalar, double.
template <SweepMode M>
float generalSloped(HeightField& f, const MillTool& tool, const Point3& a, const Point3& d,
                    double keepFrom, Stripe stripe) {
  const double lxy2 = d[0] * d[0] + d[1] * d[1], r = tool.radius;
  const double ax = a[0], ay = a[1];
  auto slope = [&](double qx, double qy, double t) {
    double ex = ax + t * d[0] - qx, ey = ay + t * d[1] - qy;
    double dist = std::sqrt(ex * ex + ey * ey);
    if (dist < 1e-12) return d[2];
    double dr = (ex * d[0] + ey * d[1]) / dist;
    double eps = 1e-9;  // numerical derivative of the profile: robust at its vertical edge
    double rr = std::min(dist, r - eps);
    double hp = (tool.profile(rr + eps) - tool.profile(std::max(rr - eps, 0.0))) / (2 * eps);
    return d[2] + hp * dr;
  };
  // Cells come in as local float coordinates; the minimisation runs in double.
  return sweepStadium<M>(f, ax, ay, d[0], d[1], r, keepFrom, stripe, [&](float rxf, float ryf) {
    double rx = rxf, ry = ryf, qx = ax + rx, qy = ay + ry;
    double s = rx * rx + ry * ry, p = rx * d[0] + ry * d[1];
    double disc = p * p - lxy2 * (s - r * r);
    if (disc < 0) return kNone;
    double root = std::sqrt(disc);
    double lo = std::max((p - root) / lxy2, 0.0), hi = std::min((p + root) / lxy2, 1.0);
    if (lo > hi) return kNone;
    for (int it = 0; it < 50 && hi - lo > 1e-12; ++it) {
      double mid = 0.5 * (lo + hi);
      if (slope(qx, qy, mid) > 0)
        hi = mid;
      else
        lo = mid;
    }
    double t = 0.5 * (lo + hi);
    double ex = ax + t * d[0] - qx, ey = ay + t * d[1] - qy;
    double dist = std::min(std::sqrt(ex * ex + ey * ey), r);
    return static_cast<float>(a[2] + t * d[2] + tool.profile(dist));
  });
}

// Where a move that continues from a point already cut may start cutting: the signed
// distance along the move (in XY, from its start) behind which the tool at the start point
// is its lowest. The envelope at a cell is min over t of z(t) + h(|q - p(t)|), convex in t.
// Behind the start (along-track a <= 0) the distance only grows with t, so a rising or level
// move is lowest at t = 0 for every such cell. A descending ball: h'(d) >= d / r, so the
// slope at t = 0 is at least dz + L |a| / r (L the move's XY length), and it is lowest at
// the start where |a| >= -dz r / L. Other profiles on a descending move: no such bound.
double keepFromAfterCut(const MillTool& tool, double lxy, double dz) {
  if (!(lxy > 0)) return kKeepAll;
  if (dz >= 0) return 0;
  if (tool.kind == MillToolKind::Ball) return dz * tool.radius / lxy;
  return kKeepAll;
}

template <SweepMode M>
NCVM_INLINE float lineImpl(HeightField& f, const MillTool& tool, const Point3& a0, const Point3& b0,
                           Stripe stripe, bool startCut) {
  Point3 a = a0, d{b0[0] - a0[0], b0[1] - a0[1], b0[2] - a0[2]};
  double lxy2 = d[0] * d[0] + d[1] * d[1];
  if (lxy2 < 1e-18) {  // a plunge or retract: the tool at its lowest point
    if (d[2] < 0) a = b0;
    d = {0, 0, 0};
    lxy2 = 0;
  }
  const double r = tool.radius;
  const bool flatMove = std::abs(d[2]) <= 1e-9;
  const double keepFrom =
      startCut ? keepFromAfterCut(tool, std::sqrt(lxy2), flatMove ? 0.0 : d[2]) : kKeepAll;
  const auto fr = static_cast<float>(r);
  switch (tool.kind) {
    case MillToolKind::Flat:
      return flatMove ? horizontal<M>(f, r, a, d[0], d[1], keepFrom, stripe, FlatProfile{})
                      : flatSloped<M>(f, r, a, d, keepFrom, stripe);
    case MillToolKind::Ball:
      if (flatMove)
        return horizontal<M>(f, r, a, d[0], d[1], keepFrom, stripe, BallProfile{fr, fr * fr});
      return startCut ? ballSloped<M, true>(f, r, a, d, keepFrom, stripe)
                      : ballSloped<M, false>(f, r, a, d, keepFrom, stripe);
    case MillToolKind::Bull: {
      auto c = static_cast<float>(tool.corner);
      BullProfile h{static_cast<float>(r - tool.corner), c, c * c};
      return flatMove ? horizontal<M>(f, r, a, d[0], d[1], keepFrom, stripe, h)
                      : generalSloped<M>(f, tool, a, d, keepFrom, stripe);
    }
    case MillToolKind::Drill:
      return flatMove ? horizontal<M>(f, r, a, d[0], d[1], keepFrom, stripe,
                                      DrillProfile{static_cast<float>(tool.coneSlope)})
                      : generalSloped<M>(f, tool, a, d, keepFrom, stripe);
  }
  return 0;
}

NCVM_CLONES float cutLine(HeightField& f, const MillTool& tool, const Point3& a, const Point3& b,
                          Stripe stripe, bool startCut) {
  return lineImpl<SweepMode::Cut>(f, tool, a, b, stripe, startCut);
}
NCVM_CLONES float measureLine(HeightField& f, const MillTool& tool, const Point3& a,
                              const Point3& b, Stripe stripe) {
  return lineImpl<SweepMode::Measure>(f, tool, a, b, stripe, false);
}

// The smallest angle-aligned box around an arc.
void arcBox(double cx, double cy, double ra, double a0, double sweep, double box[4]) {
  double a1 = a0 + sweep;
  box[0] = std::min(cx + ra * std::cos(a0), cx + ra * std::cos(a1));
  box[1] = std::max(cx + ra * std::cos(a0), cx + ra * std::cos(a1));
  box[2] = std::min(cy + ra * std::sin(a0), cy + ra * std::sin(a1));
  box[3] = std::max(cy + ra * std::sin(a0), cy + ra * std::sin(a1));
  double lo = std::min(a0, a1), hi = std::max(a0, a1);
  for (int k = static_cast<int>(std::floor(lo / (M_PI / 2))) - 1; k * (M_PI / 2) <= hi + 1e-12;
       ++k) {
    double ang = k * (M_PI / 2);
    if (ang < lo || ang > hi) continue;
    double x = cx + ra * std::cos(ang), y = cy + ra * std::sin(ang);
    box[0] = std::min(box[0], x);
    box[1] = std::max(box[1], x);
    box[2] = std::min(box[2], y);
    box[3] = std::max(box[3], y);
  }
}

// One row of an arc's cells: `count` cells from local x `wx0` (step `step`) at local y `wy`,
// local coordinates relative to the arc's mid point M (a point on the arc), m the unit
// direction from the centre to M. The distance to the arc is |rho - ra| where the cell's
// direction from the centre lies within the sweep, else the distance to the nearer end
// point. Relative to M every term stays small, so float keeps the micrometres however far
// the centre is: rho^2 - ra^2 = |w|^2 + 2 ra (w.m), and rho - ra = that / (rho + ra). The
// sector test uses cross products with the start and end directions (no atan2), so the loop
// is straight-line code the compiler vectorises.
struct ArcFrame {
  float ra, ra2, mx, my;         // radius, its square, direction to the mid point
  float sx, sy, ex, ey, c0, c1;  // start/end directions; their cross products with M - C
  float p0x, p0y, p1x, p1y;      // the end points relative to M
  bool full, wide;               // a full circle; a sweep of more than half a turn
};

template <SweepMode M, class Profile>
NCVM_INLINE float arcRow(float* z, int count, float wx0, float step, float wy, ArcFrame a,
                         float zTip, float r2, Profile h) {
  // By value and into locals: the stores to z cannot alias them, so the loop vectorises.
  const float ra = a.ra, ra2 = a.ra2, mx = a.mx, my = a.my, sx = a.sx, sy = a.sy, ex = a.ex,
              ey = a.ey, k0 = a.c0, k1 = a.c1, p0x = a.p0x, p0y = a.p0y, p1x = a.p1x, p1y = a.p1y;
  const bool full = a.full, wide = a.wide;
  float pen = 0;
  for (int k = 0; k < count; ++k) {
    float wx = wx0 + static_cast<float>(k) * step;
    float num = wx * wx + wy * wy + 2 * ra * (wx * mx + wy * my);
    float rho = std::sqrt(std::max(ra2 + num, 0.0f));
    float dr = num / (rho + ra);
    bool in0 = sx * wy - sy * wx + k0 >= 0, in1 = ex * wy - ey * wx + k1 <= 0;
    bool inside = full | (wide ? (in0 | in1) : (in0 & in1));
    float bx = wx - p0x, by = wy - p0y, ux = wx - p1x, uy = wy - p1y;
    float ends = std::min(bx * bx + by * by, ux * ux + uy * uy);
    float d2 = inside ? dr * dr : ends;
    float zt = d2 <= r2 ? zTip + h(d2) : kNone;
    float old = z[k], nz = std::min(old, zt);
    pen = std::max(pen, old - nz);
    if constexpr (M == SweepMode::Cut) z[k] = nz;
  }
  return pen;
}

template <SweepMode M, class Profile>
NCVM_INLINE float arcKernel(HeightField& f, double r, double cx, double cy, double ra, double a0,
                            double sweep, double z, Stripe stripe, Profile h) {
  // Work with a counter-clockwise sweep from `start`.
  double start = sweep >= 0 ? a0 : a0 + sweep, span = std::abs(sweep);
  double box[4];
  arcBox(cx, cy, ra, start, span, box);
  const double ro = ra + r, ri = ra - r, mid = start + span / 2;
  const double mx = std::cos(mid), my = std::sin(mid), Mx = cx + ra * mx, My = cy + ra * my;
  const double sx = std::cos(start), sy = std::sin(start);
  const double ex = std::cos(start + span), ey = std::sin(start + span);
  ArcFrame a;
  a.ra = static_cast<float>(ra);
  a.ra2 = static_cast<float>(ra * ra);
  a.mx = static_cast<float>(mx);
  a.my = static_cast<float>(my);
  a.sx = static_cast<float>(sx);
  a.sy = static_cast<float>(sy);
  a.ex = static_cast<float>(ex);
  a.ey = static_cast<float>(ey);
  a.c0 = static_cast<float>(ra * (sx * my - sy * mx));
  a.c1 = static_cast<float>(ra * (ex * my - ey * mx));
  a.p0x = static_cast<float>(ra * (sx - mx));
  a.p0y = static_cast<float>(ra * (sy - my));
  a.p1x = static_cast<float>(ra * (ex - mx));
  a.p1y = static_cast<float>(ra * (ey - my));
  a.full = span >= 2 * M_PI - 1e-12;
  a.wide = span > M_PI;
  const auto zTip = static_cast<float>(z), r2 = static_cast<float>(r * r);
  const auto step = static_cast<float>(f.cell());
  int jlo, jhi;
  f.rowsWithin(box[2] - r, box[3] + r, jlo, jhi);
  const double inv = 1 / f.cell(), x0 = f.x0() - cx;
  float pen = 0;
  for (int j = jlo; j < jhi; ++j) {
    if (!stripe.owns(j)) continue;
    const double vy = f.cellY(j) - cy;
    // Cells of interest lie in the annulus ra - r <= rho <= ra + r (the end discs too) and
    // in the arc's box grown by r: up to two intervals of the row.
    double wo2 = ro * ro - vy * vy;
    if (wo2 < 0) continue;
    const double wo = std::sqrt(wo2);
    const double lo = std::max(-wo, box[0] - r - cx), hi = std::min(wo, box[1] + r - cx);
    const double wi = ri > std::abs(vy) ? std::sqrt(ri * ri - vy * vy) : -1;
    const auto wy = static_cast<float>(f.cellY(j) - My);
    // Up to two intervals (no lambda: it would not inherit the AVX2 clone's target).
    double from[2] = {lo, std::max(lo, wi)}, to[2] = {hi, hi};
    int parts = 1;
    if (wi > 0) {
      to[0] = std::min(hi, -wi);
      parts = 2;
    }
    for (int part = 0; part < parts; ++part) {
      int ilo, ihi;
      cellsWithin(from[part], to[part], x0, inv, f.nx(), ilo, ihi);
      if (ilo >= ihi) continue;
      const auto wx0 = static_cast<float>(f.cellX(ilo) - Mx);
      pen = std::max(pen, arcRow<M>(f.row(j) + ilo, ihi - ilo, wx0, step, wy, a, zTip, r2, h));
    }
  }
  return pen;
}

template <SweepMode M>
NCVM_INLINE float arcImpl(HeightField& f, const MillTool& tool, double cx, double cy, double ra,
                          double a0, double sweep, double z, Stripe stripe) {
  const double r = tool.radius;
  const auto fr = static_cast<float>(r);
  switch (tool.kind) {
    case MillToolKind::Flat:
      return arcKernel<M>(f, r, cx, cy, ra, a0, sweep, z, stripe, FlatProfile{});
    case MillToolKind::Ball:
      return arcKernel<M>(f, r, cx, cy, ra, a0, sweep, z, stripe, BallProfile{fr, fr * fr});
    case MillToolKind::Bull: {
      auto c = static_cast<float>(tool.corner);
      BullProfile h{static_cast<float>(r - tool.corner), c, c * c};
      return arcKernel<M>(f, r, cx, cy, ra, a0, sweep, z, stripe, h);
    }
    case MillToolKind::Drill:
      return arcKernel<M>(f, r, cx, cy, ra, a0, sweep, z, stripe,
                          DrillProfile{static_cast<float>(tool.coneSlope)});
  }
  return 0;
}

NCVM_CLONES float cutArc(HeightField& f, const MillTool& tool, double cx, double cy, double ra,
                         double a0, double sweep, double z, Stripe stripe) {
  return arcImpl<SweepMode::Cut>(f, tool, cx, cy, ra, a0, sweep, z, stripe);
}
NCVM_CLONES float measureArc(HeightField& f, const MillTool& tool, double cx, double cy, double ra,
                             double a0, double sweep, double z, Stripe stripe) {
  return arcImpl<SweepMode::Measure>(f, tool, cx, cy, ra, a0, sweep, z, stripe);
}

}  // namespace

float sweepLine(HeightField& f, const MillTool& tool, const Point3& a, const Point3& b,
                Stripe stripe, SweepMode mode, bool startCut) {
  return mode == SweepMode::Cut ? cutLine(f, tool, a, b, stripe, startCut)
                                : measureLine(f, tool, a, b, stripe);
}

float sweepArcXY(HeightField& f, const MillTool& tool, double cx, double cy, double radius,
                 double a0, double sweep, double z, Stripe stripe, SweepMode mode) {
  return mode == SweepMode::Cut ? cutArc(f, tool, cx, cy, radius, a0, sweep, z, stripe)
                                : measureArc(f, tool, cx, cy, radius, a0, sweep, z, stripe);
}

float holderPenetration(const HeightField& f, double r, double lift, const Point3& a,
                        const Point3& b, Stripe stripe) {
  MillTool t;
  t.kind = MillToolKind::Flat;
  t.radius = r;
  // Measure mode never writes: the const_cast only shares the kernel.
  return measureLine(const_cast<HeightField&>(f), t, {a[0], a[1], a[2] + lift},
                     {b[0], b[1], b[2] + lift}, stripe);
}

}  // namespace ncvm
