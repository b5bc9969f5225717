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

// The insert holder's shank when the tool gives holder_diameter (its width) and
// holder_length: a rectangle whose axis passes through the nose centre, starting where the
// cutting edges end (edge_length from the nose centre). An OD tool (imaginary tip towards
// -X: tips 3, 4, 8, 0, 9, and the axial tips 5 and 7) has its shank along +X, a boring bar
// (tip towards +X: 1, 2, 6) along Z, away from the tip. Empty without a holder, and for
// drills (their body is the outline already).
std::vector<Pt> holderOutline(const ToolSpec& tool, double defaultEdge);

// Convex hull of the outline placed at a and at b: the area it sweeps moving from a to b.
// Counter-clockwise.
std::vector<Pt> sweptHull(const std::vector<Pt>& outline, Pt a, Pt b);

// The same for a convex counter-clockwise outline (sweptHull(outline, {}, {}) of any outline)
// in linear time, into `out`: the Minkowski sum of the outline and the segment, the outline's
// back chain at a and its front chain at b. Edges parallel to the move may keep collinear
// vertices.
void sweepConvex(const std::vector<Pt>& hull, Pt a, Pt b, std::vector<Pt>& out);

// The vertices of the convex counter-clockwise hull that are extreme across the direction
// d (lowest and highest cross product d x v): the sweep's two sides leave from them.
void supportsAcross(const std::vector<Pt>& hull, Pt d, size_t& lo, size_t& hi);

// The area the hull sweeps along a polyline whose segments all have the same extreme
// vertices lo and hi (supportsAcross): exactly the union of the segments' sweeps, as one
// polygon. Each segment's sweep is the convex hull of the tool at its two ends, and each
// contains the tool at the joints, so the union is bounded by the tool's back at the first
// point, the lo vertex along the path, the tool's front at the last point and the hi vertex
// back along the path; with the same extreme vertices the two sides meet at every joint
// (the tool lies on the inner side of both segments' side lines there) and the union has
// no other boundary. Counter-clockwise; with two points it is sweepConvex.
void sweepPath(const std::vector<Pt>& hull, const std::vector<Pt>& path, size_t lo, size_t hi,
               std::vector<Pt>& out);

}  // namespace ncvm::lsim
