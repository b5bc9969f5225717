#pragma once
// The height-map file ncvm writes as the final mill stock (stock.hmap) and reads as a mill
// target (target.height_map): a text header line
//   NCVM-HMAP 1 <nx> <ny> <x0> <y0> <cell>\n
// then nx*ny little-endian float32 heights, row by row from y0 upwards, each row from x0.
#include <string>

#include "sim/heightfield.hpp"

namespace ncvm {

std::string encodeHeightMap(const HeightField& f);
// Throws std::runtime_error for a missing, truncated or malformed file.
HeightField loadHeightMap(const std::string& path);

}  // namespace ncvm
