#pragma once
// Programmable mirror image (G51.1), scaling (G51) and coordinate system rotation (G68) as
// one map from the programmed work position to the work position the tool follows. The
// control applies them in a fixed order, mirror, then scaling, then rotation (30i manual
// B-63944EN-2 "Scaling and coordinate system rotation"; docs/fanuc-decisions.md). Cutter
// compensation, tool length and the work offsets come after the map, so D and H values are
// never scaled. Coordinates are X Y Z in nm (doubles, so that the map is exact enough to
// invert); other axes pass through.
#include <array>
#include <cstddef>

namespace ncvm::xform {

using P3 = std::array<double, 3>;

// The axes of a plane as (u, v): G17 X Y, G18 Z X, G19 Y Z; positive angles turn u into v.
struct PlaneAxes {
  size_t u, v;
};
PlaneAxes planeAxes(int plane);

struct Transform {
  std::array<bool, 3> mirror{};  // G51.1, per axis
  P3 mirrorAt{};                 // the mirror axis positions
  bool scaling = false;          // G51
  P3 scale{1, 1, 1};             // factors (negative: mirrored by scaling)
  P3 scaleAt{};                  // centre of scaling
  bool rotation = false;         // G68
  int rotPlane = 17;
  double cu = 0, cv = 0;  // centre of rotation after mirror and scaling
  double angle = 0;       // radians, counter-clockwise in the rotation plane as applied

  bool active() const { return mirror[0] || mirror[1] || mirror[2] || scaling || rotation; }
  // Programmed -> actual, and back (for positions the tool reached without a programmed
  // end point, such as G53).
  P3 apply(const P3& p) const;
  P3 invert(const P3& p) const;
  // Only the linear part (directions such as the I/J/K of G40).
  P3 applyVector(const P3& d) const;
  // Mirror and scaling reverse the sense of turning in `plane` when an odd number of its
  // two axes is reflected: G02/G03 and G41/G42 swap.
  bool flips(int plane) const;
  // G68: centre and angle as programmed; the centre goes through the mirror and the
  // scaling in effect, and the angle changes sign when they reflect the plane.
  void setRotation(int plane, double u, double v, double degrees);
};

}  // namespace ncvm::xform
