#pragma once
// G31 against the mill stock: where a ball moving along a segment first touches the height
// field. Each cell is the square column it stands for — its XY square, from the field's
// bottom up to its height — and the contact is exact for those columns (no stepping along
// the path): the first touch of the ball with a column is the first entry of its centre
// into the column grown by the radius (three face slabs, twelve edge cylinders, eight
// corner spheres), and the first contact is the earliest over the columns near the path.
//
// Error bound against the surface that was really cut: a cell is cut when its centre is
// inside the tool, so a wall of the model lies within half a cell of the true wall along
// each axis (floors and top faces are exact to the float heights, well under 1 µm). A
// ball probing a wall along its normal therefore latches within cell / 2 of the true
// contact; a bore centre taken from two opposite contacts is within cell / 2 as well.
#include <optional>

#include "sim/heightfield.hpp"
#include "sim/probe_world.hpp"

namespace ncvm {

// Fraction t in [0, 1] of a->b (the field's coordinates and units) where a ball of radius r
// centred on the segment first touches a column; 0 when it touches at a; nullopt if never.
// Outside the field there is no material.
std::optional<double> heightFieldFirstContact(const HeightField& f, const Vec3& a, const Vec3& b,
                                              double r);

}  // namespace ncvm
