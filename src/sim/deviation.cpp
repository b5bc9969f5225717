#include "sim/deviation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

namespace ncvm {

namespace {
constexpr std::array<double, 8> kEdges = {-5, -3, -2, -1, 1, 2, 3, 5};  // in tolerances
}

nlohmann::json deviationJson(const std::vector<DeviationSample>& samples, double tolerance) {
  nlohmann::json j;
  j["tolerance"] = tolerance;
  j["samples"] = samples.size();
  double total = 0, sumAbs = 0, maxAbs = 0, maxExcess = 0, maxGouge = 0, inTol = 0;
  std::array<double, kEdges.size() + 1> band{};
  for (const auto& s : samples) {
    total += s.weight;
    sumAbs += std::fabs(s.d) * s.weight;
    maxAbs = std::max(maxAbs, std::fabs(s.d));
    maxExcess = std::max(maxExcess, s.d);
    maxGouge = std::max(maxGouge, -s.d);
    if (std::fabs(s.d) <= tolerance) inTol += s.weight;
    size_t k = 0;
    // A deviation exactly on an edge belongs to the band nearer zero.
    while (k < kEdges.size() &&
           (s.d > 0 ? s.d > kEdges[k] * tolerance : s.d >= kEdges[k] * tolerance))
      ++k;
    band[k] += s.weight;
  }
  j["max"] = maxAbs;
  j["mean"] = total > 0 ? sumAbs / total : 0.0;
  j["max_excess"] = maxExcess;
  j["max_gouge"] = maxGouge;
  j["in_tolerance"] = total > 0 ? inTol / total : 1.0;
  nlohmann::json bands = nlohmann::json::array();
  for (size_t k = 0; k < band.size(); ++k) {
    nlohmann::json b;
    b["from"] = k == 0 ? nlohmann::json(nullptr) : nlohmann::json(kEdges[k - 1] * tolerance);
    b["to"] = k == kEdges.size() ? nlohmann::json(nullptr) : nlohmann::json(kEdges[k] * tolerance);
    b["share"] = total > 0 ? band[k] / total : 0.0;
    bands.push_back(b);
  }
  j["bands"] = bands;
  j["measured"] = true;
  if (!(total > 0)) markNotMeasured(j, "no point of the target was measured");
  return j;
}

void markNotMeasured(nlohmann::json& summary, const std::string& why) {
  static const char* kStatistics[] = {"max",           "mean",        "max_excess", "max_gouge",
                                      "in_tolerance",  "mean_signed", "area",       "uncut_area",
                                      "uncut_share",   "gouge_area",  "share",      "at_max",
                                      "at_max_excess", "at_max_gouge"};
  for (const char* key : kStatistics)
    if (summary.contains(key)) summary[key] = nullptr;
  if (summary.contains("bands"))
    for (auto& b : summary["bands"]) {
      b["share"] = nullptr;
      if (b.contains("area")) b["area"] = nullptr;
    }
  summary["measured"] = false;
  summary["not_measured"] = why;
}

std::string notMeasuredText(const nlohmann::json& summary) {
  if (!summary.is_object() || summary.value("measured", true)) return {};
  return "not measured (" + summary.value("not_measured", std::string("no sample")) + ")";
}

const char* deviationColour(double d, double tolerance) {
  static const char* excess[] = {"#2ca02c", "#fdd49e", "#fc8d59", "#e34a33", "#b30000"};
  static const char* gouge[] = {"#2ca02c", "#c6dbef", "#6baed6", "#2171b5", "#08306b"};
  double t = std::fabs(d) / tolerance;
  size_t k = t <= 1 ? 0 : t <= 2 ? 1 : t <= 3 ? 2 : t <= 5 ? 3 : 4;
  return d >= 0 ? excess[k] : gouge[k];
}

}  // namespace ncvm
