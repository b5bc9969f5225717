#pragma once
// The physical milling tool as the stock simulation sees it: a solid of revolution about
// the spindle axis whose lower surface is a profile h(r), the height above the tip at
// radius r. Built from the setup's [tools.T] description, never from the D offset (seed
// 002: the offset may differ from the cutter's real radius).
#include <cmath>
#include <stdexcept>
#include <string>

#include "machine/setup.hpp"

namespace ncvm {

enum class MillToolKind : uint8_t { Flat, Ball, Bull, Drill };

struct MillTool {
  MillToolKind kind = MillToolKind::Flat;
  double radius = 0;        // cutter radius (half the diameter)
  double corner = 0;        // corner radius (ball: = radius; bull: 0 < corner < radius)
  double coneSlope = 0;     // drill: dh/dr = 1 / tan(point angle / 2)
  double fluteLength = 0;   // cutting length above the tip; 0 = the whole stick-out cuts
  double holderRadius = 0;  // holder radius; 0 = no holder check
  double holderZ = 0;       // holder lower face above the tip

  // Height of the lower surface above the tip at radial distance r (0 <= r <= radius).
  double profile(double r) const {
    switch (kind) {
      case MillToolKind::Flat:
        return 0;
      case MillToolKind::Ball:
        return radius - std::sqrt(std::max(0.0, radius * radius - r * r));
      case MillToolKind::Bull: {
        double flat = radius - corner;
        if (r <= flat) return 0;
        double u = r - flat;
        return corner - std::sqrt(std::max(0.0, corner * corner - u * u));
      }
      case MillToolKind::Drill:
        return r * coneSlope;
    }
    return 0;
  }
  // Height of the tool's widest point above the tip: above it the tool is a cylinder.
  double profileTop() const { return profile(radius); }
};

struct ToolError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The tool for [tools.T]: flat, ball, bull (corner_radius), face (flat, or bull with a corner
// radius), drill (point_angle). Throws ToolError for a missing diameter or an impossible shape.
MillTool millToolFromSpec(const ToolSpec& spec, int toolNumber);

}  // namespace ncvm
