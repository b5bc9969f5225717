#pragma once
// The part a lathe insert can make ([target] reachable = "nose"): the region behind the target
// contour closed by a disc of the nose radius, so the contour's concave corners are rounded by
// r the way any real insert leaves them (docs/stock-analysis.md). Vericut-like verifiers
// compare the stock with this boundary and report the rounded corners apart as unreachable.
#include <polyclipping/clipper.hpp>
#include <vector>

#include "sim/lathe_insert.hpp"

namespace ncvm {

struct ReachablePart {
  ClipperLib::Paths part;      // the closed part region, integer (z, r) units
  double unreachableArea = 0;  // between the sharp part and the reachable one
  int corners = 0;             // separate pieces of that area (one per concave corner)
  bool found = false;          // false: the contour did not separate part from air
};

// contour: the (shifted) target chain, (r, z) in program units. stock: the final profile,
// used to tell the part side of the contour from the air side (the side that kept most of
// its raw material). raw: the raw stock rectangle. scale: integer units per program unit.
ReachablePart reachablePart(const std::vector<lsim::Pt>& contour, const ClipperLib::Paths& stock,
                            const ClipperLib::Path& raw, double noseRadius, double arcTolerance,
                            double minCornerArea, double scale);

}  // namespace ncvm
