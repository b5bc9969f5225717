#pragma once
// The cutting shape of a lathe tool in the half-profile plane (r = radius, z): the insert's
// nose circle at the nose centre, which lies opposite the imaginary tip (tip directions as
// drawn by Fanuc, X up, Z right), and its two cutting edges; or a drill's point and body on
// the spindle axis. Outlines are convex polygons relative to the programmed point.
#include <vector>

#include "machine/setup.hpp"

namespace ncvm::lsim {

struct Pt {
  double r = 0, z = 0;
};

// Unit vector from the nose centre towards the imaginary tip for tip 1-8 ((0, 0) for 0/9).
Pt tipDirection(int tip);

// The tool's outline relative to the programmed point. chordError bounds the distance
// between the polygon and the true nose circle (vertices lie on a circle slightly larger
// than the nose, so the error is split both ways); defaultEdge is the edge (or drill body)
// length when the tool gives none.
std::vector<Pt> toolOutline(const ToolSpec& tool, double chordError, double defaultEdge);

// Convex hull of the outline placed at a and at b: the area it sweeps moving from a to b.
// Counter-clockwise.
std::vector<Pt> sweptHull(const std::vector<Pt>& outline, Pt a, Pt b);

}  // namespace ncvm::lsim
