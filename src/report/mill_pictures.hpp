#pragma once
// Pictures of a mill stock, seen from above (+Y up, +X right), at most `maxSide` pixels on
// the long side (every n-th cell):
//  - height map: grey level proportional to height, lowest black, top white;
//  - top view: the surface shaded by a light from the north-west, with cells left more than
//    the tolerance above the target in red (uncut) and cells cut below it in blue (gouge);
//  - deviation map: blue (gouge) through green (within tolerance) to red (excess),
//    saturating at 10 tolerances; cells outside the target region grey.
#include "report/png_writer.hpp"
#include "sim/heightfield.hpp"
#include "sim/mill_analysis.hpp"

namespace ncvm {

RgbImage millHeightMap(const HeightField& f, int maxSide = 1600);
RgbImage millTopView(const HeightField& f, const MillTarget* target, int maxSide = 1600);
RgbImage millDeviationMap(const HeightField& f, const MillTarget& target, int maxSide = 1600);

}  // namespace ncvm
