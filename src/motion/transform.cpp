#include "motion/transform.hpp"

#include <cmath>
#include <numbers>

namespace ncvm::xform {

PlaneAxes planeAxes(int plane) {
  if (plane == 18) return {2, 0};
  if (plane == 19) return {1, 2};
  return {0, 1};
}

namespace {
// Mirror, then scaling: one reflection-and-stretch per axis.
P3 stretch(const Transform& t, P3 p) {
  for (size_t k = 0; k < 3; ++k) {
    if (t.mirror[k]) p[k] = 2.0 * t.mirrorAt[k] - p[k];
    if (t.scaling) p[k] = t.scaleAt[k] + t.scale[k] * (p[k] - t.scaleAt[k]);
  }
  return p;
}
}  // namespace

P3 Transform::apply(const P3& in) const {
  P3 p = stretch(*this, in);
  if (rotation) {
    const PlaneAxes a = planeAxes(rotPlane);
    double du = p[a.u] - cu, dv = p[a.v] - cv;
    double c = std::cos(angle), s = std::sin(angle);
    p[a.u] = cu + c * du - s * dv;
    p[a.v] = cv + s * du + c * dv;
  }
  return p;
}

P3 Transform::invert(const P3& in) const {
  P3 p = in;
  if (rotation) {
    const PlaneAxes a = planeAxes(rotPlane);
    double du = p[a.u] - cu, dv = p[a.v] - cv;
    double c = std::cos(angle), s = std::sin(angle);
    p[a.u] = cu + c * du + s * dv;
    p[a.v] = cv - s * du + c * dv;
  }
  for (size_t k = 0; k < 3; ++k) {
    if (scaling) p[k] = scaleAt[k] + (p[k] - scaleAt[k]) / scale[k];
    if (mirror[k]) p[k] = 2.0 * mirrorAt[k] - p[k];
  }
  return p;
}

P3 Transform::applyVector(const P3& d) const {
  P3 o = apply(P3{0, 0, 0}), e = apply(d);
  return {e[0] - o[0], e[1] - o[1], e[2] - o[2]};
}

bool Transform::flips(int plane) const {
  const PlaneAxes a = planeAxes(plane);
  auto reflected = [&](size_t k) { return mirror[k] != (scaling && scale[k] < 0); };
  return reflected(a.u) != reflected(a.v);
}

void Transform::setRotation(int plane, double u, double v, double degrees) {
  const PlaneAxes a = planeAxes(plane);
  P3 c{};
  c[a.u] = u;
  c[a.v] = v;
  c = stretch(*this, c);
  rotation = true;
  rotPlane = plane;
  cu = c[a.u];
  cv = c[a.v];
  angle = degrees * std::numbers::pi / 180.0 * (flips(plane) ? -1.0 : 1.0);
}

}  // namespace ncvm::xform
