#pragma once
// Pictures of a mill stock, seen from above (+Y up, +X right), at most `maxSide` pixels on
// the long side (every n-th cell):
//  - height map: a colour scale from the lowest cell (dark violet) to the highest (yellow),
//    heightColour() (the report draws the same scale as its legend);
//  - top view: the surface shaded by a light from the north-west, with cells left more than
//    the tolerance above the target in red (uncut) and cells cut below it in blue (gouge);
//  - deviation map: blue (gouge) through green (within tolerance) to red (excess),
//    saturating at 10 tolerances; cells outside the target region grey.
#include <array>
#include <utility>

#include "report/png_writer.hpp"
#include "sim/heightfield.hpp"
#include "sim/mill_analysis.hpp"

namespace ncvm {

// The height map's colours: u = 0 (lowest) dark violet, through teal and green, to u = 1
// (highest) yellow; lightness rises with u, so it reads in grey too.
std::array<double, 3> heightColour(double u);
// The deviation map's colour of a deviation (stock - target) with the tolerance `tol`:
// green within it, towards red (excess) or blue (gouge) on a log scale saturating at 10 tol.
std::array<double, 3> millDeviationColour(double dev, double tol);
// The lowest and highest cell of the field: the ends of the height map's scale.
std::pair<float, float> heightRange(const HeightField& f);

RgbImage millHeightMap(const HeightField& f, int maxSide = 1600);
RgbImage millTopView(const HeightField& f, const MillTarget* target, int maxSide = 1600);
RgbImage millDeviationMap(const HeightField& f, const MillTarget& target, int maxSide = 1600);

}  // namespace ncvm
