#pragma once
// The mill stock as a closed triangle mesh (binary STL): the height field's top surface,
// four walls and the bottom, sampled on a grid of at most `maxSamples` points per side.
#include <string>

#include "sim/heightfield.hpp"

namespace ncvm {

std::string encodeStl(const HeightField& f, int maxSamples = 300);
void writeStl(const std::string& path, const HeightField& f, int maxSamples = 300);

}  // namespace ncvm
