#pragma once
// G31 against the lathe half-profile. The stock is a solid of revolution about Z; the
// distance from a ball centre (x, y, z) to it is the distance, in the centre's own
// half-plane through the axis (rho = sqrt(x² + y²), z), to the profile's polygons: exact,
// to their edges. The first contact is found by sphere tracing on that distance (each step
// is the distance less the radius, so no contact is stepped over), as for [[solids]].
// Coordinates: the stock's, X and Y radial (not diameters), program units.
#include <optional>
#include <polyclipping/clipper.hpp>
#include <vector>

#include "sim/probe_world.hpp"

namespace ncvm {

class ProfileProbe {
 public:
  // paths: the profile as LatheStock keeps it (X = z, Y = radius), `scale` integer units
  // per program unit; outer rings and holes, counted even-odd.
  ProfileProbe(const ClipperLib::Paths& paths, double scale);
  // Signed distance from (rho, z) to the profile: negative inside the material.
  double distance(double rho, double z) const;
  std::optional<double> firstContact(const Vec3& a, const Vec3& b, double r) const;

 private:
  struct Edge {
    double z0, r0, z1, r1;
  };
  std::vector<Edge> edges_;
};

}  // namespace ncvm
