#include "timing/profile.hpp"

#include <algorithm>
#include <cmath>

namespace ncvm::timing {

namespace {
bool unlimited(const Ramp& r) {
  return !(r.a > 0) || std::isinf(r.a);
}
bool trapezoid(const Ramp& r) {
  return !(r.j > 0) || std::isinf(r.j);
}
}  // namespace

double rampTime(double dv, const Ramp& r) {
  if (dv <= 0 || unlimited(r)) return 0;
  if (trapezoid(r)) return dv / r.a;
  // Jerk-limited: the acceleration rises to a (a/j), holds, and falls again; when dv is too
  // small to reach a, it rises and falls in two halves of sqrt(dv/j) each.
  if (dv >= r.a * r.a / r.j) return dv / r.a + r.a / r.j;
  return 2.0 * std::sqrt(dv / r.j);
}

double rampDistance(double v0, double v1, const Ramp& r) {
  // Symmetric ramps: the mean velocity is the mean of the end velocities.
  return 0.5 * (v0 + v1) * rampTime(std::fabs(v1 - v0), r);
}

double reachable(double v0, double d, const Ramp& r) {
  if (d <= 0) return v0;
  if (unlimited(r)) return 1e300;
  if (trapezoid(r)) return std::sqrt(v0 * v0 + 2.0 * r.a * d);
  // Distance at which the ramp just reaches the full acceleration (dv = a^2/j).
  double dvStar = r.a * r.a / r.j;
  double dStar = (2.0 * v0 + dvStar) * r.a / r.j;
  if (d <= dStar) {
    // d = (2 v0 + s^2) s / sqrt(j) with s = sqrt(dv): the depressed cubic
    // s^3 + 2 v0 s - d sqrt(j) = 0 has one real root (Cardano).
    double p = 2.0 * v0, q = d * std::sqrt(r.j);
    double disc = std::sqrt(q * q / 4.0 + p * p * p / 27.0);
    double s = std::cbrt(q / 2.0 + disc) + std::cbrt(q / 2.0 - disc);
    return v0 + s * s;
  }
  // d = v0 dv/a + v0 a/j + dv^2/(2a) + dv a/(2j): a quadratic in dv.
  double A = 1.0 / (2.0 * r.a), B = v0 / r.a + r.a / (2.0 * r.j), C = v0 * r.a / r.j - d;
  double dv = (-B + std::sqrt(std::max(0.0, B * B - 4.0 * A * C))) / (2.0 * A);
  return v0 + dv;
}

double blockTime(double v0, double v1, double vmax, double len, const Ramp& r) {
  if (len <= 0) return 0;
  vmax = std::max({vmax, v0, v1});
  if (!(vmax > 0)) return 0;
  if (unlimited(r)) return len / vmax;
  double up = rampDistance(v0, vmax, r), down = rampDistance(vmax, v1, r);
  if (up + down <= len)
    return rampTime(vmax - v0, r) + rampTime(vmax - v1, r) + (len - up - down) / vmax;
  // The block is too short to reach vmax: find the peak velocity vp that uses it exactly.
  double lo = std::max(v0, v1);
  if (rampDistance(v0, v1, r) >= len) return v0 + v1 > 0 ? 2.0 * len / (v0 + v1) : 0;
  double vp;
  if (trapezoid(r)) {
    vp = std::sqrt((2.0 * r.a * len + v0 * v0 + v1 * v1) / 2.0);
  } else {
    double hi = vmax;
    for (int k = 0; k < 60 && hi - lo > 1e-12 * hi; ++k) {
      double mid = 0.5 * (lo + hi);
      if (rampDistance(v0, mid, r) + rampDistance(mid, v1, r) > len)
        hi = mid;
      else
        lo = mid;
    }
    vp = 0.5 * (lo + hi);
  }
  return rampTime(vp - v0, r) + rampTime(vp - v1, r);
}

}  // namespace ncvm::timing
