#include "sim/probe_world.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncvm {

namespace {

double len(double x, double y) {
  return std::sqrt(x * x + y * y);
}
double len(double x, double y, double z) {
  return std::sqrt(x * x + y * y + z * z);
}

// Exact signed distances (negative inside the material).
double boxDistance(const SolidWorld::Solid& s, const Vec3& p) {
  double q[3], outside = 0, inside = -std::numeric_limits<double>::infinity();
  for (int k = 0; k < 3; ++k) {
    auto K = static_cast<size_t>(k);
    double c = (s.a[K] + s.b[K]) / 2, h = (s.b[K] - s.a[K]) / 2;
    q[k] = std::fabs(p[K] - c) - h;
    outside += std::max(q[k], 0.0) * std::max(q[k], 0.0);
    inside = std::max(inside, q[k]);
  }
  return std::sqrt(outside) + std::min(inside, 0.0);
}

double cylinderDistance(const SolidWorld::Solid& s, const Vec3& p) {
  double dr = len(p[0] - s.a[0], p[1] - s.a[1]) - s.radius;
  double dz = std::max(s.bottom - p[2], p[2] - s.top);
  return std::min(std::max(dr, dz), 0.0) + len(std::max(dr, 0.0), std::max(dz, 0.0));
}

// A hole of `radius` through a slab from bottom to top; the slab reaches out to `outer`
// (a ring) or without end.
double boreDistance(const SolidWorld::Solid& s, const Vec3& p) {
  double r = len(p[0] - s.a[0], p[1] - s.a[1]);
  double inHole = s.radius - r;  // > 0 inside the hole
  double beyond = s.outer > 0 ? r - s.outer : -std::numeric_limits<double>::infinity();
  double dz = std::max(s.bottom - p[2], p[2] - s.top);
  // The material is {radius <= r <= outer} x {bottom <= z <= top}: an annulus extruded.
  double dRadial = std::max(inHole, beyond);
  return std::min(std::max(dRadial, dz), 0.0) + len(std::max(dRadial, 0.0), std::max(dz, 0.0));
}

double planeDistance(const SolidWorld::Solid& s, const Vec3& p) {
  return (p[0] - s.a[0]) * s.n[0] + (p[1] - s.a[1]) * s.n[1] + (p[2] - s.a[2]) * s.n[2];
}

}  // namespace

double SolidWorld::distance(const Vec3& p) const {
  double d = std::numeric_limits<double>::infinity();
  for (const Solid& s : solids_) {
    switch (s.kind) {
      case Solid::Box:
        d = std::min(d, boxDistance(s, p));
        break;
      case Solid::Cylinder:
        d = std::min(d, cylinderDistance(s, p));
        break;
      case Solid::Bore:
        d = std::min(d, boreDistance(s, p));
        break;
      case Solid::Plane:
        d = std::min(d, planeDistance(s, p));
        break;
    }
  }
  return d;
}

std::optional<double> SolidWorld::firstContact(const Vec3& a, const Vec3& b, double r) const {
  if (solids_.empty()) return std::nullopt;
  double L = len(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
  auto at = [&](double t) {
    return Vec3{a[0] + (b[0] - a[0]) * t, a[1] + (b[1] - a[1]) * t, a[2] + (b[2] - a[2]) * t};
  };
  constexpr double kTouch = 1e-7;  // mm: far below the 0.001 mm the control latches
  if (distance(a) - r <= kTouch) return 0.0;
  if (L == 0) return std::nullopt;
  // Sphere tracing: the signed distance is a safe step, so the first contact is never
  // stepped over. Grazing approaches converge slowly, hence the bisection fallback.
  double t = 0;
  for (int it = 0; it < 100000; ++it) {
    double d = distance(at(t)) - r;
    if (d <= kTouch) return t;
    t += d / L;
    if (t > 1.0) {
      return distance(at(1.0)) - r <= kTouch ? std::optional<double>(1.0) : std::nullopt;
    }
  }
  double lo = t, hi = 1.0;
  if (distance(at(hi)) - r > kTouch) return std::nullopt;
  for (int it = 0; it < 100; ++it) {
    double mid = (lo + hi) / 2;
    (distance(at(mid)) - r > kTouch ? lo : hi) = mid;
  }
  return hi;
}

std::unique_ptr<SolidWorld> SolidWorld::fromSetup(const Setup& setup,
                                                  const std::function<Vec3(int)>& workShift) {
  auto world = std::make_unique<SolidWorld>();
  for (size_t k = 0; k < setup.solids.size(); ++k) {
    const SolidSpec& sp = setup.solids[k];
    std::string key = fmt::format("solids.{}", k);
    auto need = [&](bool ok, const char* what) {
      if (!ok)
        throw SetupError(
            fmt::format("{}: a {} needs {}", key, sp.kind.empty() ? "solid" : sp.kind, what), key,
            sp.line);
    };
    need(!sp.kind.empty(), "kind");
    Vec3 shift{};
    if (sp.frame != "machine") shift = workShift(workOffsetIndex(sp.frame));
    auto pt = [&](const std::vector<double>& v) {
      return Vec3{v[0] + shift[0], v[1] + shift[1], (v.size() > 2 ? v[2] : 0.0) + shift[2]};
    };
    Solid s{};
    if (sp.kind == "box") {
      need(sp.min.size() == 3 && sp.max.size() == 3, "min and max [x, y, z]");
      s.kind = Solid::Box;
      s.a = pt(sp.min);
      s.b = pt(sp.max);
      for (size_t i = 0; i < 3; ++i) need(s.a[i] < s.b[i], "min below max on every axis");
    } else if (sp.kind == "cylinder" || sp.kind == "bore") {
      need(!sp.center.empty(), "center [x, y]");
      need(sp.diameter > 0, "a positive diameter");
      s.kind = sp.kind == "bore" ? Solid::Bore : Solid::Cylinder;
      s.a = pt(sp.center);
      s.radius = sp.diameter / 2;
      s.outer = sp.outerDiameter / 2;
      need(s.outer == 0 || s.outer > s.radius, "outer_diameter larger than diameter");
      s.top = sp.top + shift[2];
      s.bottom = sp.bottom <= -1e9 ? -1e9 : sp.bottom + shift[2];
      need(s.bottom < s.top, "bottom below top");
    } else {
      need(sp.point.size() == 3 && sp.normal.size() == 3, "point and normal [x, y, z]");
      s.kind = Solid::Plane;
      s.a = pt(sp.point);
      double n = len(sp.normal[0], sp.normal[1], sp.normal[2]);
      need(n > 0, "a non-zero normal");
      s.n = Vec3{sp.normal[0] / n, sp.normal[1] / n, sp.normal[2] / n};
    }
    world->add(s);
  }
  return world;
}

}  // namespace ncvm
