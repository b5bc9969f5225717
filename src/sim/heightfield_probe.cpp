#include "sim/heightfield_probe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncvm {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// A start this close counts as touching, as in SolidWorld: far below the 0.001 mm latch.
constexpr double kTouch = 1e-7;

struct Box {
  double lo[3], hi[3];
};

double boxDistance(const Box& b, const Vec3& p) {
  double s = 0;
  for (size_t k = 0; k < 3; ++k) {
    double d = std::max({b.lo[k] - p[k], 0.0, p[k] - b.hi[k]});
    s += d * d;
  }
  return std::sqrt(s);
}

// First t in [0, 1] at which a + t d is inside [lo, hi] (slab method); kInf if never.
double slabEntry(const double* lo, const double* hi, const Vec3& a, const Vec3& d) {
  double t0 = 0, t1 = 1;
  for (size_t k = 0; k < 3; ++k) {
    if (d[k] == 0) {
      if (a[k] < lo[k] || a[k] > hi[k]) return kInf;
      continue;
    }
    double ta = (lo[k] - a[k]) / d[k], tb = (hi[k] - a[k]) / d[k];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return kInf;
  }
  return t0;
}

// First root in [0, 1] of A t² + B t + C = 0 for a point that starts outside (C > 0).
double firstRoot(double A, double B, double C) {
  if (A <= 0) return kInf;
  double disc = B * B - 4 * A * C;
  if (disc < 0) return kInf;
  double t = (-B - std::sqrt(disc)) / (2 * A);
  return t >= 0 && t <= 1 ? t : kInf;
}

// First t at which the centre a + t d comes within r of the box, for a start farther than r:
// the earliest entry into one of the parts of the grown box (the box grown along one axis,
// a cylinder around an edge, a sphere around a corner), which together make it up.
double columnEntry(const Box& b, const Vec3& a, const Vec3& d, double r) {
  double glo[3], ghi[3];
  for (size_t k = 0; k < 3; ++k) glo[k] = b.lo[k] - r, ghi[k] = b.hi[k] + r;
  if (slabEntry(glo, ghi, a, d) == kInf) return kInf;  // misses the grown box's bounds
  double best = kInf;
  for (size_t k = 0; k < 3; ++k) {
    double lo[3] = {b.lo[0], b.lo[1], b.lo[2]}, hi[3] = {b.hi[0], b.hi[1], b.hi[2]};
    lo[k] -= r;
    hi[k] += r;
    best = std::min(best, slabEntry(lo, hi, a, d));
  }
  if (r <= 0) return best;
  for (size_t k = 0; k < 3; ++k) {
    // Edges along axis k; their end discs lie inside the corner spheres.
    size_t u = (k + 1) % 3, w = (k + 2) % 3;
    double A = d[u] * d[u] + d[w] * d[w];
    for (double cu : {b.lo[u], b.hi[u]}) {
      for (double cw : {b.lo[w], b.hi[w]}) {
        double qu = a[u] - cu, qw = a[w] - cw;
        double t = firstRoot(A, 2 * (qu * d[u] + qw * d[w]), qu * qu + qw * qw - r * r);
        if (t >= best) continue;
        double s = a[k] + t * d[k];
        if (s >= b.lo[k] && s <= b.hi[k]) best = t;
      }
    }
  }
  const double A = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  for (int c = 0; c < 8; ++c) {
    double q[3], B = 0, C = -r * r;
    for (size_t k = 0; k < 3; ++k) {
      q[k] = a[k] - ((c >> k) & 1 ? b.hi[k] : b.lo[k]);
      B += 2 * q[k] * d[k];
      C += q[k] * q[k];
    }
    best = std::min(best, firstRoot(A, B, C));
  }
  return best;
}

}  // namespace

std::optional<double> heightFieldFirstContact(const HeightField& f, const Vec3& a, const Vec3& b,
                                              double r) {
  r = std::max(r, 0.0);
  const Vec3 d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double c = f.cell(), zb = f.bottom();
  const double top = static_cast<double>(f.top());
  // The path in chunks, each searched over the columns its ball can reach; a contact found
  // within the chunk is the first one, since every column touched earlier lies in an
  // earlier chunk (or this one). Chunks about the ball's size keep the columns per chunk few.
  const double step = std::max(r, 4 * c);
  const int n = len > 0 ? static_cast<int>(std::min(1e6, std::ceil(len / step))) : 1;
  double best = kInf;
  for (int k = 0; k < n; ++k) {
    const double t0 = static_cast<double>(k) / n,
                 t1 = k + 1 == n ? 1.0 : static_cast<double>(k + 1) / n;
    double lo[3], hi[3];
    for (size_t q = 0; q < 3; ++q) {
      double p0 = a[q] + t0 * d[q], p1 = a[q] + t1 * d[q];
      lo[q] = std::min(p0, p1) - r;
      hi[q] = std::max(p0, p1) + r;
    }
    if (hi[2] < zb || lo[2] > top) continue;  // below the block or above anything left
    const double x0 = f.x0(), y0 = f.y0();
    if (hi[0] < x0 || lo[0] > x0 + f.nx() * c || hi[1] < y0 || lo[1] > y0 + f.ny() * c) continue;
    auto index = [&](double v, double origin, int count) {
      return static_cast<int>(std::clamp(std::floor((v - origin) / c), 0.0, count - 1.0));
    };
    const int i0 = index(lo[0], x0, f.nx()), i1 = index(hi[0], x0, f.nx());
    const int j0 = index(lo[1], y0, f.ny()), j1 = index(hi[1], y0, f.ny());
    for (int j = j0; j <= j1; ++j) {
      const float* row = f.row(j);
      for (int i = i0; i <= i1; ++i) {
        const double h = row[i];
        if (h < lo[2] || h <= zb) continue;  // out of the ball's reach, or cut through
        Box box{{x0 + i * c, y0 + j * c, zb}, {x0 + (i + 1) * c, y0 + (j + 1) * c, h}};
        if (k == 0 && boxDistance(box, a) <= r + kTouch) return 0.0;
        best = std::min(best, columnEntry(box, a, d, r));
      }
    }
    if (best <= t1) return best;
  }
  return best <= 1 ? std::optional<double>(best) : std::nullopt;
}

}  // namespace ncvm
