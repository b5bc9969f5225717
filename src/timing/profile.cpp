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
  if (vmax > 0 && v0 == vmax && v1 == vmax) return len / vmax;  // the common case: cruising through
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

namespace {
// The root of f(t) = s on [0, hi] for f increasing and convex there (true of each cubic phase
// of a jerk-limited ramp): Newton's steps from the right end fall monotonically onto the root.
template <class F, class D>
double convexRoot(F f, D df, double s, double hi) {
  double t = hi;
  for (int k = 0; k < 40; ++k) {
    double slope = df(t);
    if (!(slope > 0)) break;
    double step = (f(t) - s) / slope;
    if (!(step > 1e-15 * hi)) break;
    t = std::max(0.0, t - step);
  }
  return t;
}

// Time at which a ramp from v0 up by dv has covered distance s: each phase in closed form
// (the constant-acceleration middle) or by Newton's method (the two cubic ends), not by
// bisection; this runs once for every block that ends inside a ramp.
double rampTimeAt(double v0, double dv, const Ramp& r, double s) {
  double total = rampTime(dv, r);
  if (s <= 0 || total <= 0) return 0;
  if (trapezoid(r)) {
    double disc = v0 * v0 + 2.0 * r.a * s;
    return (std::sqrt(disc) - v0) / r.a;
  }
  bool full = dv >= r.a * r.a / r.j;
  double j = r.j, t1 = full ? r.a / r.j : std::sqrt(dv / r.j), am = j * t1,
         t2 = full ? dv / r.a - r.a / r.j : 0.0;
  double da = v0 * t1 + j * t1 * t1 * t1 / 6.0;
  if (s <= da)
    return convexRoot([&](double t) { return v0 * t + j * t * t * t / 6.0; },
                      [&](double t) { return v0 + 0.5 * j * t * t; }, s, t1);
  double va = v0 + 0.5 * j * t1 * t1;
  double db = da + va * t2 + 0.5 * am * t2 * t2;
  if (s <= db) {
    double tau = (std::sqrt(std::max(0.0, va * va + 2.0 * am * (s - da))) - va) / am;
    return t1 + std::clamp(tau, 0.0, t2);
  }
  double vb = va + am * t2;
  double dEnd = db + vb * t1 + 0.5 * am * t1 * t1 - j * t1 * t1 * t1 / 6.0;
  if (s >= dEnd) return total;
  double tau =
      convexRoot([&](double u) { return db + vb * u + 0.5 * am * u * u - j * u * u * u / 6.0; },
                 [&](double u) { return vb + am * u - 0.5 * j * u * u; }, s, t1);
  return t1 + t2 + tau;
}
}  // namespace

Profile makeProfile(double v0, double v1, double vmax, double len, const Ramp& r) {
  Profile p;
  p.v0 = v0, p.v1 = v1, p.len = len, p.r = r;
  if (len <= 0) return p;
  vmax = std::max({vmax, v0, v1});
  if (unlimited(r)) {
    p.vp = vmax;
    p.tCruise = vmax > 0 ? len / vmax : 0;
    return p;
  }
  double up = rampDistance(v0, vmax, r), down = rampDistance(vmax, v1, r);
  if (up + down <= len) {
    p.vp = vmax;
  } else if (rampDistance(v0, v1, r) >= len) {
    // Not reachable within len (the planner avoids it): a straight change.
    p.vp = std::max(v0, v1);
  } else if (trapezoid(r)) {
    p.vp = std::sqrt((2.0 * r.a * len + v0 * v0 + v1 * v1) / 2.0);
  } else {
    double lo = std::max(v0, v1), hi = vmax;
    for (int k = 0; k < 60 && hi - lo > 1e-12 * hi; ++k) {
      double mid = 0.5 * (lo + hi);
      (rampDistance(v0, mid, r) + rampDistance(mid, v1, r) > len ? hi : lo) = mid;
    }
    p.vp = lo;  // the side that fits in len
  }
  p.dUp = rampDistance(v0, p.vp, r), p.tUp = rampTime(p.vp - v0, r);
  p.dDown = rampDistance(p.vp, v1, r), p.tDown = rampTime(p.vp - v1, r);
  double cruise = len - p.dUp - p.dDown;
  if (cruise < 0 && cruise > -1e-9 * len) cruise = 0;
  if (cruise < 0) {
    // The straight change of the unreachable case: constant mean speed.
    p.dUp = p.dDown = p.tUp = p.tDown = 0;
    p.tCruise = v0 + v1 > 0 ? 2.0 * len / (v0 + v1) : 0;
    p.vp = 0.5 * (v0 + v1);
    return p;
  }
  p.tCruise = p.vp > 0 ? cruise / p.vp : 0;
  return p;
}

double Profile::timeOutsideCruise(double s) const {
  if (s <= 0) return 0;
  if (s >= len) return total();
  if (s <= dUp) return rampTimeAt(v0, vp - v0, r, s);
  double cruiseEnd = len - dDown;
  if (s <= cruiseEnd) return tUp + (vp > 0 ? (s - dUp) / vp : 0);
  // The down-ramp, read backwards as an up-ramp from v1.
  return total() - rampTimeAt(v1, vp - v1, r, len - s);
}

}  // namespace ncvm::timing
