#include "sim/lathe_probe.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ncvm {

ProfileProbe::ProfileProbe(const ClipperLib::Paths& paths, double scale) {
  for (const auto& path : paths) {
    for (size_t k = 0; k < path.size(); ++k) {
      const auto& p = path[k];
      const auto& q = path[(k + 1) % path.size()];
      edges_.push_back({static_cast<double>(p.X) / scale, static_cast<double>(p.Y) / scale,
                        static_cast<double>(q.X) / scale, static_cast<double>(q.Y) / scale});
    }
  }
}

double ProfileProbe::distance(double rho, double z) const {
  double best = std::numeric_limits<double>::infinity();
  bool inside = false;
  for (const Edge& e : edges_) {
    double dz = e.z1 - e.z0, dr = e.r1 - e.r0;
    double len2 = dz * dz + dr * dr;
    double u = len2 > 0 ? std::clamp(((z - e.z0) * dz + (rho - e.r0) * dr) / len2, 0.0, 1.0) : 0.0;
    best = std::min(best, std::hypot(z - (e.z0 + u * dz), rho - (e.r0 + u * dr)));
    // Even-odd crossing count along +z from the point.
    if ((e.r0 > rho) != (e.r1 > rho)) {
      double zc = e.z0 + (rho - e.r0) / (e.r1 - e.r0) * dz;
      if (zc > z) inside = !inside;
    }
  }
  return inside ? -best : best;
}

std::optional<double> ProfileProbe::firstContact(const Vec3& a, const Vec3& b, double r) const {
  if (edges_.empty()) return std::nullopt;
  const double L = std::sqrt((b[0] - a[0]) * (b[0] - a[0]) + (b[1] - a[1]) * (b[1] - a[1]) +
                             (b[2] - a[2]) * (b[2] - a[2]));
  auto gap = [&](double t) {
    double x = a[0] + (b[0] - a[0]) * t, y = a[1] + (b[1] - a[1]) * t;
    return distance(std::hypot(x, y), a[2] + (b[2] - a[2]) * t) - r;
  };
  constexpr double kTouch = 1e-7;  // as SolidWorld: far below the 0.001 mm latch
  if (gap(0) <= kTouch) return 0.0;
  if (L == 0) return std::nullopt;
  // The distance in the half-plane is the 3D distance to the solid of revolution, so it
  // is a safe step along the segment. Grazing approaches converge slowly: bisection then.
  double t = 0;
  for (int it = 0; it < 20000; ++it) {
    double d = gap(t);
    if (d <= kTouch) return t;
    t += d / L;
    if (t > 1.0) return gap(1.0) <= kTouch ? std::optional<double>(1.0) : std::nullopt;
  }
  double lo = t, hi = 1.0;
  if (gap(hi) > kTouch) return std::nullopt;
  for (int it = 0; it < 100; ++it) {
    double mid = (lo + hi) / 2;
    (gap(mid) > kTouch ? lo : hi) = mid;
  }
  return hi;
}

}  // namespace ncvm
