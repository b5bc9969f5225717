#include "server/viewer_tools.hpp"

#include <algorithm>
#include <string>

#include "sim/lathe_insert.hpp"
#include "sim/mill_tools.hpp"

namespace ncvm::server {

namespace {

nlohmann::json points(const std::vector<lsim::Pt>& pts) {
  nlohmann::json out = nlohmann::json::array();
  for (const auto& p : pts) out.push_back({p.r, p.z});
  return out;
}

nlohmann::json latheTool(const ToolSpec& spec, double unit) {
  // As the lathe stock model takes it: 10 mm (0.4 in) edges when none is given.
  const double edge = 10 * unit;
  return {{"type", spec.type},
          {"outline", points(lsim::toolOutline(spec, 0.005 * unit, edge))},
          {"holder", points(lsim::holderOutline(spec, edge))}};
}

nlohmann::json millTool(const ToolSpec& spec, int number) {
  if (spec.type == "probe" || spec.type == "insert")
    return {{"type", spec.type}, {"diameter", spec.diameter}};
  const MillTool t = millToolFromSpec(spec, number);
  nlohmann::json profile = nlohmann::json::array();
  constexpr int kSteps = 24;
  for (int k = 0; k <= kSteps; ++k) {
    const double r = t.radius * k / kSteps;
    profile.push_back({r, t.profile(r)});
  }
  // A face mill is a wide, short body; others stand about two diameters out (or as long as
  // their flutes).
  const double drawn = t.fluteLength > 0 ? t.fluteLength
                                         : std::max(t.profileTop(), 0.0) +
                                               (spec.type == "face" ? 0.35 : 2.0) * spec.diameter;
  nlohmann::json holder = nullptr;
  if (t.holderRadius > 0)
    holder = {{"radius", t.holderRadius}, {"z", t.holderZ}, {"length", spec.holderLength}};
  return {{"type", spec.type},
          {"diameter", spec.diameter},
          {"profile", profile},
          {"length", drawn},
          {"holder", holder}};
}

}  // namespace

nlohmann::json viewerTools(const Setup& setup) {
  nlohmann::json out = nlohmann::json::object();
  const double unit = setup.initialUnit == InputUnit::Inch ? 1 / 25.4 : 1.0;
  for (const auto& [number, spec] : setup.tools) {
    try {
      out[std::to_string(number)] =
          setup.kind == MachineKind::Lathe ? latheTool(spec, unit) : millTool(spec, number);
    } catch (const std::exception&) {
      // Not a shape the simulation models (no diameter, say): the generic tool.
    }
  }
  return out;
}

}  // namespace ncvm::server
