#pragma once
// The setup's physical tools ([tools.T]) as the web page draws them at the tool's place: the
// shapes the stock simulation cuts with, so that the page has no second copy of them.
//   mill:  {"type", "diameter", "profile": [[r, h], ...] (the lower surface, h above the
//          tip at radius r, r from 0 to the radius), "length" (the cutting length drawn),
//          "holder": {"radius", "z", "length"} or null}; a probe: {"type", "diameter"}
//   lathe: {"type", "outline": [[r, z], ...], "holder": [[r, z], ...]}: the insert (or
//          drill) and its shank relative to the programmed point, r a radius (sim/lathe_insert)
// In the program's units; a tool the simulation cannot model is left out (the page then
// draws its generic tool).
#include <nlohmann/json.hpp>

#include "machine/setup.hpp"

namespace ncvm::server {

nlohmann::json viewerTools(const Setup& setup);

}  // namespace ncvm::server
