#include "machine/timing_keys.hpp"

#include <stdexcept>

namespace ncvm {

namespace {
double number(const TimingValue& v) {
  if (auto* d = std::get_if<double>(&v)) return *d;
  throw std::invalid_argument("expected a number");
}
double nonNegative(const TimingValue& v) {
  double d = number(v);
  if (!(d >= 0)) throw std::invalid_argument("must not be negative");
  return d;
}
double positive(const TimingValue& v) {
  double d = number(v);
  if (!(d > 0)) throw std::invalid_argument("must be positive");
  return d;
}
bool boolean(const TimingValue& v) {
  if (auto* b = std::get_if<bool>(&v)) return *b;
  throw std::invalid_argument("expected true or false");
}
}  // namespace

void applyTimingKey(TimingSetup& t, const std::string& key, const TimingValue& v) {
  // Per-axis values: timing.axes.X.rapid_t1 or, for all axes, timing.rapid_t1.
  std::string field = key;
  int axis = -1;
  if (key.rfind("axes.", 0) == 0) {
    static const std::string names = "XYZABC";
    if (key.size() < 8 || key[6] != '.' || names.find(key[5]) == std::string::npos)
      throw std::invalid_argument("per-axis keys are timing.axes.X.<key> (X Y Z A B C)");
    axis = static_cast<int>(names.find(key[5]));
    field = key.substr(7);
  }
  AxisArray* perAxis = nullptr;
  if (field == "rapid_t1")
    perAxis = &t.rapidT1Ms;
  else if (field == "rapid_t2")
    perAxis = &t.rapidT2Ms;
  else if (field == "accel")
    perAxis = &t.accel;
  else if (field == "corner_speed_difference")
    perAxis = &t.cornerSpeedDiff;
  if (perAxis) {
    double d =
        field == "accel" || field == "corner_speed_difference" ? positive(v) : nonNegative(v);
    if (axis >= 0)
      (*perAxis)[static_cast<size_t>(axis)] = d;
    else
      perAxis->fill(d);
    return;
  }
  if (axis >= 0)
    throw std::invalid_argument("per-axis keys: rapid_t1 rapid_t2 accel corner_speed_difference");
  if (field == "model") {
    auto* s = std::get_if<std::string>(&v);
    if (!s || (*s != "simple" && *s != "dynamic"))
      throw std::invalid_argument("expected \"simple\" or \"dynamic\"");
    t.dynamic = *s == "dynamic";
  } else if (field == "accel_change_time")
    t.accelChangeMs = nonNegative(v);
  else if (field == "lookahead_blocks") {
    double d = positive(v);
    if (d != static_cast<double>(static_cast<int>(d)) || d > 1000)
      throw std::invalid_argument("a whole number from 1 to 1000");
    t.lookaheadBlocks = static_cast<int>(d);
  } else if (field == "arc_clamp_feed")
    t.arcClampFeed = nonNegative(v);
  else if (field == "arc_clamp_radius")
    t.arcClampRadius = positive(v);
  else if (field == "arc_clamp_min_feed")
    t.arcClampMinFeed = nonNegative(v);
  else if (field == "block_time")
    t.minBlockTimeMs = nonNegative(v);
  else if (field == "in_position_time")
    t.inPositionS = nonNegative(v);
  else if (field == "tool_change_time")
    t.toolChangeS = nonNegative(v);
  else if (field == "t_code_time")
    t.tCodeS = nonNegative(v);
  else if (field == "m_code_time")
    t.mCodeS = nonNegative(v);
  else if (field == "coolant_time")
    t.coolantS = nonNegative(v);
  else if (field == "spindle_accel")
    t.spindleAccel = positive(v);
  else if (field == "spindle_wait")
    t.spindleWait = boolean(v);
  else if (field == "operation_comments")
    t.operationComments = boolean(v);
  else if (field == "feed_override")
    t.feedOverride = positive(v);
  else if (field == "rapid_override")
    t.rapidOverride = positive(v);
  else if (field == "threads")
    throw std::invalid_argument(
        "removed: the time stage runs on the control's thread (its worker thread did not pay, "
        "docs/performance.md)");
  else
    throw std::invalid_argument(
        "timing keys: model rapid_t1 rapid_t2 accel corner_speed_difference accel_change_time "
        "lookahead_blocks "
        "arc_clamp_feed arc_clamp_radius arc_clamp_min_feed block_time in_position_time "
        "tool_change_time t_code_time m_code_time coolant_time spindle_accel spindle_wait "
        "feed_override "
        "rapid_override operation_comments, axes.X.<per-axis key>");
}

}  // namespace ncvm
