#include "sim/mill_tools.hpp"

#include <fmt/format.h>

namespace ncvm {

MillTool millToolFromSpec(const ToolSpec& spec, int toolNumber) {
  auto fail = [&](const std::string& why) {
    throw ToolError(fmt::format("tools.{}: {}", toolNumber, why));
  };
  if (!(spec.diameter > 0)) fail("the stock simulation needs the cutter's diameter");
  MillTool t;
  t.radius = spec.diameter / 2;
  t.fluteLength = std::max(0.0, spec.fluteLength);
  const std::string& type = spec.type;
  if (type == "flat" || type == "face") {
    t.kind = spec.cornerRadius > 0 ? MillToolKind::Bull : MillToolKind::Flat;
    t.corner = spec.cornerRadius;
  } else if (type == "ball") {
    t.kind = MillToolKind::Ball;
    t.corner = t.radius;
  } else if (type == "bull") {
    if (!(spec.cornerRadius > 0)) fail("a bull-nose end mill needs corner_radius > 0");
    t.kind = MillToolKind::Bull;
    t.corner = spec.cornerRadius;
  } else if (type == "drill") {
    if (!(spec.pointAngle > 0 && spec.pointAngle < 180))
      fail("point_angle must be between 0 and 180");
    t.kind = MillToolKind::Drill;
    t.coneSlope = 1.0 / std::tan(spec.pointAngle * M_PI / 360.0);
  } else {
    fail(fmt::format("type \"{}\" does not cut (flat, ball, bull, face, drill)", type));
  }
  if (t.kind == MillToolKind::Bull) {
    if (t.corner > t.radius) fail("corner_radius is larger than the cutter radius");
    if (t.corner == t.radius) t.kind = MillToolKind::Ball;
  }
  // Holder: its lower face is length - holder_length above the tip (both measured from the
  // spindle gauge line, docs/setup-format.md).
  if (spec.holderDiameter > 0 && spec.length > 0 && spec.holderLength > 0 &&
      spec.length > spec.holderLength) {
    t.holderRadius = spec.holderDiameter / 2;
    t.holderZ = spec.length - spec.holderLength;
  }
  return t;
}

}  // namespace ncvm
