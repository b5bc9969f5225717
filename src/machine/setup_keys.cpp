#include "machine/setup_keys.hpp"

#include <algorithm>
#include <sstream>

#include "core/edit_distance.hpp"

namespace ncvm {

namespace {
std::vector<std::string> split(const std::string& key) {
  std::vector<std::string> parts;
  std::stringstream in(key);
  for (std::string part; std::getline(in, part, '.');) parts.push_back(part);
  return parts;
}

}  // namespace

const std::vector<std::string>& setupKeyNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> k;
    auto add = [&](const std::string& head, std::initializer_list<const char*> fields) {
      for (const char* f : fields) k.push_back(head + "." + f);
    };
    add("machine",
        {"kind", "control", "gcode_system", "program_number_digits", "increment", "units"});
    add("switches", {"optional_stop"});
    add("limits", {"max_blocks", "max_time_s", "max_line_length", "max_file_bytes",
                   "max_trace_bytes", "macro_nesting", "subprogram_nesting", "total_nesting"});
    add("clock", {"date", "time"});
    add("output", {"dprnt"});
    add("block_skip", {"N"});
    add("axes.X", {"present", "rapid", "initial", "rotary", "diameter", "min", "max", "reference"});
    add("tool_offsets.N", {"h_geometry", "h_wear", "d_geometry", "d_wear", "x", "x_wear", "z",
                           "z_wear", "r", "r_wear", "y", "y_wear", "t", "tip"});
    add("tools.N",
        {"type", "diameter", "corner_radius", "length", "point_angle", "flute_length",
         "nose_radius", "tip", "insert_angle", "edge_length", "holder_diameter", "holder_length"});
    add("probe", {"tool", "ball_diameter", "miss_alarm", "use_stock", "length_to"});
    add("solids.N", {"kind", "frame", "center", "min", "max", "point", "normal", "diameter",
                     "outer_diameter", "top", "bottom"});
    add("stock", {"frame", "diameter", "bore_diameter", "length", "front_z", "min", "max", "cell"});
    add("target",
        {"blocks", "polyline", "shift", "reachable", "face_z", "height_map", "tolerance"});
    add("timing", {"model",
                   "rapid_t1",
                   "rapid_t2",
                   "accel",
                   "corner_speed_difference",
                   "accel_change_time",
                   "lookahead_blocks",
                   "arc_clamp_feed",
                   "arc_clamp_radius",
                   "arc_clamp_min_feed",
                   "block_time",
                   "in_position_time",
                   "tool_change_time",
                   "t_code_time",
                   "m_code_time",
                   "coolant_time",
                   "spindle_accel",
                   "spindle_wait",
                   "operation_comments",
                   "feed_override",
                   "rapid_override"});
    add("timing.axes.X", {"rapid_t1", "rapid_t2", "accel", "corner_speed_difference"});
    for (const char* alias : {"DPI", "NAT", "LRP", "PRT", "TCS", "CCV", "CLV", "SBM", "M3B", "TVC"})
      k.push_back(alias);
    return k;
  }();
  return names;
}

std::optional<std::string> nearestSetupKey(const std::string& key) {
  const std::vector<std::string> parts = split(key);
  std::optional<std::string> best;
  size_t bestDistance = std::max<size_t>(2, key.size() / 4) + 1;
  for (const auto& name : setupKeyNames()) {
    std::vector<std::string> pattern = split(name);
    if (pattern.size() != parts.size()) continue;
    // The placeholders take the mistyped key's own segments: only the names are compared.
    for (size_t k = 0; k < pattern.size(); ++k)
      if (pattern[k] == "X" || pattern[k] == "N") pattern[k] = parts[k];
    std::string candidate;
    for (const auto& p : pattern) candidate += (candidate.empty() ? "" : ".") + p;
    const size_t d = editDistance(key, candidate);
    if (d > 0 && d < bestDistance) {
      bestDistance = d;
      best = candidate;
    }
  }
  return best;
}

}  // namespace ncvm
