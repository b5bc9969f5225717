// The lathe stock's end of run: the deviation of the final profile from the target, and
// the files (profile CSV and SVG, deviation plot, revolved picture, analysis.json).
#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "report/atomic_file.hpp"
#include "report/png_writer.hpp"
#include "sim/lathe_stock.hpp"

namespace ncvm {

using lsim::Pt;

namespace {

struct Edge {
  Pt a, b;
};

// Edges of the final profile bucketed by z, for distance and inside queries.
class EdgeIndex {
 public:
  EdgeIndex(const ClipperLib::Paths& paths, double cell) : cell_(cell) {
    double s = LatheStock::kScale;
    for (const auto& p : paths)
      for (size_t k = 0; k < p.size(); ++k) {
        const auto& q0 = p[k];
        const auto& q1 = p[(k + 1) % p.size()];
        edges_.push_back({{static_cast<double>(q0.Y) / s, static_cast<double>(q0.X) / s},
                          {static_cast<double>(q1.Y) / s, static_cast<double>(q1.X) / s}});
      }
    if (edges_.empty()) return;
    z0_ = std::numeric_limits<double>::infinity();
    double z1 = -z0_;
    for (const auto& e : edges_)
      z0_ = std::min({z0_, e.a.z, e.b.z}), z1 = std::max({z1, e.a.z, e.b.z});
    cells_.resize(static_cast<size_t>((z1 - z0_) / cell_) + 1);
    for (size_t i = 0; i < edges_.size(); ++i) {
      auto [lo, hi] = std::minmax(edges_[i].a.z, edges_[i].b.z);
      for (size_t c = index(lo); c <= index(hi); ++c) cells_[c].push_back(static_cast<uint32_t>(i));
    }
  }
  size_t index(double z) const {
    double k = std::floor((z - z0_) / cell_);
    return static_cast<size_t>(std::clamp(k, 0.0, static_cast<double>(cells_.size() - 1)));
  }
  // Distance to the nearest edge (infinity without edges).
  double distance(Pt p) const {
    if (edges_.empty()) return std::numeric_limits<double>::infinity();
    double best = std::numeric_limits<double>::infinity();
    for (double R = cell_;; R *= 2) {
      for (size_t c = index(p.z - R), last = index(p.z + R); c <= last; ++c)
        for (uint32_t i : cells_[c]) best = std::min(best, segDistance(p, edges_[i]));
      bool coversAll = index(p.z - R) == 0 && index(p.z + R) == cells_.size() - 1;
      if (best <= R || coversAll) return best;
    }
  }
  // Even-odd count of the edges a ray from p towards +r crosses.
  bool inside(Pt p) const {
    if (edges_.empty() || p.z < z0_ || p.z > z0_ + cell_ * static_cast<double>(cells_.size()))
      return false;
    bool in = false;
    for (uint32_t i : cells_[index(p.z)]) {
      const Edge& e = edges_[i];
      if ((e.a.z <= p.z) == (e.b.z <= p.z)) continue;
      double r = e.a.r + (p.z - e.a.z) / (e.b.z - e.a.z) * (e.b.r - e.a.r);
      if (r > p.r) in = !in;
    }
    return in;
  }

 private:
  static double segDistance(Pt p, const Edge& e) {
    double dz = e.b.z - e.a.z, dr = e.b.r - e.a.r, L2 = dz * dz + dr * dr;
    double t = L2 > 0 ? std::clamp(((p.z - e.a.z) * dz + (p.r - e.a.r) * dr) / L2, 0.0, 1.0) : 0.0;
    return std::hypot(p.z - e.a.z - t * dz, p.r - e.a.r - t * dr);
  }
  double cell_, z0_ = 0;
  std::vector<Edge> edges_;
  std::vector<std::vector<uint32_t>> cells_;
};

std::string svgPath(const ClipperLib::Paths& paths, double sign) {
  std::string d;
  for (const auto& p : paths) {
    for (size_t k = 0; k < p.size(); ++k)
      d += fmt::format("{}{:.5f},{:.5f} ", k ? "L" : "M",
                       static_cast<double>(p[k].X) / LatheStock::kScale,
                       -sign * static_cast<double>(p[k].Y) / LatheStock::kScale);
    d += "Z ";
  }
  return d;
}

}  // namespace

double LatheStock::targetNoseRadius() const {
  return setup_.target.polyline.empty() && noseTarget_ >= 0 ? noseTarget_ : noseMax_;
}

std::vector<LatheStock::Sample> LatheStock::measureReachable(const ClipperLib::Paths& final,
                                                             ReachablePart& reach) const {
  std::vector<Sample> out;
  Pt shift{setup_.target.shift[0] / 2, setup_.target.shift[1]};
  std::vector<Pt> chain;
  for (const auto& s : target_) {
    Pt a{s.a.r + shift.r, s.a.z + shift.z}, b{s.b.r + shift.r, s.b.z + shift.z};
    if (chain.empty() || std::hypot(chain.back().r - a.r, chain.back().z - a.z) > 0)
      chain.push_back(a);
    chain.push_back(b);
  }
  auto I = [](double v) { return static_cast<ClipperLib::cInt>(std::llround(v * kScale)); };
  ClipperLib::Path raw{
      {I(zBack_), I(rIn_)}, {I(zFront_), I(rIn_)}, {I(zFront_), I(rOut_)}, {I(zBack_), I(rOut_)}};
  double r = targetNoseRadius();
  // A fillet piece smaller than 1% of a right-angle corner's is rounding, not a corner.
  double minCorner = std::max(tol_ * tol_, 0.01 * r * r * (1 - std::numbers::pi / 4));
  reach = reachablePart(chain, final, raw, r, chord_ * kScale, minCorner, kScale);
  if (!reach.found) return out;
  // Samples along the reachable boundary where it follows the contour (within r of it; the
  // rest is the raw stock's own outline), each tagged with the nearest contour block.
  double total = 0;
  for (const auto& s : target_) total += std::hypot(s.b.r - s.a.r, s.b.z - s.a.z);
  double h = std::max(tol_ / 2, total / 200000);
  EdgeIndex index(final, std::max(tileWidth_, tol_ * 10));
  auto nearest = [&](Pt p, int& n) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& s : target_) {
      Edge e{{s.a.r + shift.r, s.a.z + shift.z}, {s.b.r + shift.r, s.b.z + shift.z}};
      double dz = e.b.z - e.a.z, dr = e.b.r - e.a.r, L2 = dz * dz + dr * dr;
      double t =
          L2 > 0 ? std::clamp(((p.z - e.a.z) * dz + (p.r - e.a.r) * dr) / L2, 0.0, 1.0) : 0.0;
      double d = std::hypot(p.z - e.a.z - t * dz, p.r - e.a.r - t * dr);
      if (d < best) best = d, n = s.n;
    }
    return best;
  };
  for (const auto& path : reach.part)
    for (size_t k = 0; k < path.size(); ++k) {
      Pt a{static_cast<double>(path[k].Y) / kScale, static_cast<double>(path[k].X) / kScale};
      const auto& q = path[(k + 1) % path.size()];
      Pt b{static_cast<double>(q.Y) / kScale, static_cast<double>(q.X) / kScale};
      double L = std::hypot(b.r - a.r, b.z - a.z);
      int m = std::max(1, static_cast<int>(std::ceil(L / h)));
      for (int j = 0; j < m; ++j) {
        double t = (j + 0.5) / m;
        Pt p{a.r + (b.r - a.r) * t, a.z + (b.z - a.z) * t};
        int n = -1;
        if (nearest(p, n) > r + tol_) continue;
        double d = index.distance(p);
        out.push_back({p, index.inside(p) ? d : -d, n});
      }
    }
  return out;
}

std::vector<LatheStock::Sample> LatheStock::measure(const ClipperLib::Paths& final,
                                                    ReachablePart* reach) const {
  std::vector<Sample> out;
  if (target_.empty()) return out;
  if (reach && setup_.target.reachable == "nose") {
    out = measureReachable(final, *reach);
    if (reach->found) return out;
  }
  double total = 0;
  for (const auto& s : target_) total += std::hypot(s.b.r - s.a.r, s.b.z - s.a.z);
  double h = std::max(tol_ / 2, total / 200000);
  EdgeIndex index(final, std::max(tileWidth_, tol_ * 10));
  Pt shift{setup_.target.shift[0] / 2, setup_.target.shift[1]};
  for (const auto& s : target_) {
    double L = std::hypot(s.b.r - s.a.r, s.b.z - s.a.z);
    int n = std::max(1, static_cast<int>(std::ceil(L / h)));
    for (int k = 0; k < n; ++k) {
      double t = (k + 0.5) / n;
      Pt p{s.a.r + (s.b.r - s.a.r) * t + shift.r, s.a.z + (s.b.z - s.a.z) * t + shift.z};
      // Only where the raw stock had material is there anything to compare.
      // (A target point outside it would read as a gouge of material that never existed.)
      constexpr double eps = 1e-9;
      if (p.r < rIn_ - eps || p.r > rOut_ + eps || p.z < zBack_ - eps || p.z > zFront_ + eps ||
          p.r < 0)
        continue;
      double d = index.distance(p);
      out.push_back({p, index.inside(p) ? d : -d, s.n});
    }
  }
  return out;
}

nlohmann::json LatheStock::finish(const std::string& outDir) {
  ClipperLib::Paths final = profile();
  ReachablePart reach;
  std::vector<Sample> samples = measure(final, &reach);
  nlohmann::json a;
  a["kind"] = "lathe";
  a["units"] = unit_ < 1 ? "inch" : "mm";
  a["stock"] = {{"diameter", rOut_ * 2},
                {"bore_diameter", rIn_ * 2},
                {"length", zFront_ - zBack_},
                {"front_z", zFront_}};
  a["moves"] = moves_;
  a["cutting_moves"] = cuttingMoves_;
  a["removed_area"] = removed_;
  a["final_area"] = area();
  a["collisions"] = collisions_;
  a["tools"] = tools_;
  a["notes"] = notes_;
  a["unreachable"] = nullptr;  // reachable = "nose" only
  if (setup_.target.present) {
    double total = 0;
    for (const auto& s : target_) total += std::hypot(s.b.r - s.a.r, s.b.z - s.a.z);
    a["target"] = {{"source", targetSource_},
                   {"segments", target_.size()},
                   {"length", total},
                   {"measured_points", samples.size()}};
    std::vector<DeviationSample> ds;
    const Sample *worst = nullptr, *excess = nullptr, *gouge = nullptr;
    for (const auto& s : samples) {
      ds.push_back({s.d, 1.0});
      if (!worst || std::fabs(s.d) > std::fabs(worst->d)) worst = &s;
      if (s.d > 0 && (!excess || s.d > excess->d)) excess = &s;
      if (s.d < 0 && (!gouge || s.d < gouge->d)) gouge = &s;
    }
    a["deviation"] = deviationJson(ds, tol_);
    auto where = [](const Sample* q) {
      return q ? nlohmann::json{{"x", q->p.r * 2}, {"z", q->p.z}, {"d", q->d}, {"n", q->n}}
               : nlohmann::json(nullptr);
    };
    a["deviation"]["at_max"] = where(worst);
    a["deviation"]["at_max_excess"] = where(excess);
    a["deviation"]["at_max_gouge"] = where(gouge);
    if (target_.empty()) {
      a["notes"].push_back("target: no feed move of the block range ran");
      markNotMeasured(a["deviation"], "no feed move of the target's " + targetSource_ +
                                          " ran, so the target has no contour");
    }
    a["target"]["reachable"] = setup_.target.reachable;
    if (setup_.target.reachable == "nose") {
      a["target"]["nose_radius"] = targetNoseRadius();
      if (reach.found)
        a["unreachable"] = {{"area", reach.unreachableArea}, {"corners", reach.corners}};
      else if (!target_.empty())
        a["notes"].push_back(
            "target: reachable = \"nose\": the contour does not part the raw stock into part "
            "and cut-away air; measured against the sharp contour");
    }
  } else {
    a["target"] = nullptr;
    a["deviation"] = nullptr;
  }
  a["pictures"] = nlohmann::json::array();
  a["files"] = nlohmann::json::object();
  if (!outDir.empty()) {
    std::filesystem::create_directories(outDir);
    writeOutputs(outDir, final, samples, a);
    writeFileAtomic((std::filesystem::path(outDir) / "analysis.json").string(), a.dump(2) + "\n");
  }
  return a;
}

nlohmann::json LatheStock::writeOutputs(const std::string& dir, const ClipperLib::Paths& final,
                                        const std::vector<Sample>& samples,
                                        nlohmann::json& a) const {
  namespace fs = std::filesystem;
  auto file = [&](const char* name) { return (fs::path(dir) / name).string(); };
  double s = kScale;

  // profile.csv: every ring of the final profile, X as a diameter like the program.
  std::string csv = "ring,hole,x,z\n";
  for (size_t k = 0; k < final.size(); ++k) {
    bool hole = !ClipperLib::Orientation(final[k]);
    for (const auto& q : final[k])
      csv += fmt::format("{},{},{:.6f},{:.6f}\n", k, hole ? 1 : 0, 2 * static_cast<double>(q.Y) / s,
                         static_cast<double>(q.X) / s);
  }
  writeFileAtomic(file("profile.csv"), csv);
  a["files"]["profile_csv"] = "profile.csv";

  // profile.svg: the section through the axis (Z right, X up), raw stock dashed, the target
  // coloured by deviation on the upper half.
  double zlo = zBack_, zhi = zFront_, rhi = rOut_;
  for (const auto& t : target_)
    zlo = std::min({zlo, t.a.z, t.b.z}), zhi = std::max({zhi, t.a.z, t.b.z});
  double span = std::max(zhi - zlo, 2 * rhi), pad = span * 0.05;
  double W = 900, scale = W / (zhi - zlo + 2 * pad), H = (2 * rhi + 2 * pad) * scale;
  double stroke = 1.5 / scale;
  std::string svg = fmt::format(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
      "viewBox=\"{:.5f} {:.5f} {:.5f} {:.5f}\">\n",
      W, H, zlo - pad, -rhi - pad, zhi - zlo + 2 * pad, 2 * rhi + 2 * pad);
  svg += fmt::format(
      "<rect x=\"{:.5f}\" y=\"{:.5f}\" width=\"{:.5f}\" height=\"{:.5f}\" fill=\"none\" "
      "stroke=\"#999\" stroke-width=\"{:.5f}\" stroke-dasharray=\"{:.5f}\"/>\n",
      zBack_, -rOut_, zFront_ - zBack_, 2 * rOut_, stroke, 4 * stroke);
  svg += fmt::format(
      "<path d=\"{}\" fill=\"#c8c8c8\" fill-rule=\"evenodd\" stroke=\"#333\" "
      "stroke-width=\"{:.5f}\"/>\n",
      svgPath(final, 1), stroke);
  svg += fmt::format(
      "<path d=\"{}\" fill=\"#e4e4e4\" fill-rule=\"evenodd\" stroke=\"#777\" "
      "stroke-width=\"{:.5f}\"/>\n",
      svgPath(final, -1), stroke);
  svg += fmt::format(
      "<line x1=\"{:.5f}\" y1=\"0\" x2=\"{:.5f}\" y2=\"0\" stroke=\"#555\" stroke-width=\"{:.5f}\" "
      "stroke-dasharray=\"{:.5f} {:.5f} {:.5f} {:.5f}\"/>\n",
      zlo - pad, zhi + pad, stroke / 2, 12 * stroke, 3 * stroke, 2 * stroke, 3 * stroke);
  // Consecutive samples of one colour form one polyline.
  for (size_t k = 0; k < samples.size();) {
    const char* colour = deviationColour(samples[k].d, tol_);
    std::string pts;
    size_t j = k;
    // At most about 4000 points in all: every stride-th sample, and each run's last.
    size_t stride = std::max<size_t>(1, samples.size() / 4000);
    for (; j < samples.size() && deviationColour(samples[j].d, tol_) == colour; ++j) {
      bool last = j + 1 == samples.size() || deviationColour(samples[j + 1].d, tol_) != colour;
      if ((j - k) % stride == 0 || last)
        pts += fmt::format("{:.5f},{:.5f} ", samples[j].p.z, -samples[j].p.r);
    }
    if (j == k + 1) pts += fmt::format("{:.5f},{:.5f} ", samples[k].p.z + stroke, -samples[k].p.r);
    svg += fmt::format(
        "<polyline points=\"{}\" fill=\"none\" stroke=\"{}\" stroke-width=\"{:.5f}\"/>\n", pts,
        colour, 2.5 * stroke);
    k = j;
  }
  svg += "</svg>\n";
  writeFileAtomic(file("profile.svg"), svg);
  a["pictures"].push_back(
      {{"file", "profile.svg"},
       {"title", "Final profile (section through the axis); target coloured by deviation"},
       {"extent", {{"z", {zlo - pad, zhi + pad}}, {"radius", {-rhi - pad, rhi + pad}}}}});

  // deviation.svg: the signed deviation along the target, with the tolerance band.
  if (!samples.empty()) {
    double dmax = tol_ * 2;
    for (const auto& q : samples) dmax = std::max(dmax, std::fabs(q.d) * 1.1);
    double PW = 900, PH = 300, mx = 60, my = 20;
    auto X = [&](size_t i) {
      return mx + (PW - 2 * mx) * static_cast<double>(i) /
                      static_cast<double>(std::max<size_t>(1, samples.size() - 1));
    };
    auto Y = [&](double d) { return my + (PH - 2 * my) * (dmax - d) / (2 * dmax); };
    std::string p = fmt::format(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{:.0f}\" height=\"{:.0f}\" "
        "font-family=\"sans-serif\" font-size=\"11\">\n",
        PW, PH);
    p += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"#e5f5e0\"/>\n",
        mx, Y(tol_), PW - 2 * mx, Y(-tol_) - Y(tol_));
    p += fmt::format(
        "<line x1=\"{:.1f}\" y1=\"{:.1f}\" x2=\"{:.1f}\" y2=\"{:.1f}\" stroke=\"#888\"/>\n", mx,
        Y(0), PW - mx, Y(0));
    p += fmt::format(
        "<rect x=\"{:.1f}\" y=\"{:.1f}\" width=\"{:.1f}\" height=\"{:.1f}\" fill=\"none\" "
        "stroke=\"#333\"/>\n",
        mx, my, PW - 2 * mx, PH - 2 * my);
    // The tolerance labels only where they do not run into the zero label.
    std::vector<double> ticks{dmax, 0.0, -dmax};
    if (Y(-tol_) - Y(0) > 12) ticks.insert(ticks.end(), {tol_, -tol_});
    for (double v : ticks)
      p += fmt::format("<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"end\">{:+.4f}</text>\n",
                       mx - 4, Y(v) + 4, v);
    std::string pts;
    size_t stride = std::max<size_t>(1, samples.size() / 4000);
    for (size_t i = 0; i < samples.size(); i += stride)
      pts += fmt::format("{:.2f},{:.2f} ", X(i), Y(samples[i].d));
    p += fmt::format(
        "<polyline points=\"{}\" fill=\"none\" stroke=\"#b30000\" stroke-width=\"1.5\"/>\n", pts);
    p += fmt::format(
        "<text x=\"{:.1f}\" y=\"{:.1f}\" text-anchor=\"middle\">along the target contour (excess "
        "+, gouge -), tolerance {}</text>\n",
        PW / 2, PH - 4, tol_);
    p += "</svg>\n";
    writeFileAtomic(file("deviation.svg"), p);
    a["pictures"].push_back(
        {{"file", "deviation.svg"}, {"title", "Deviation along the target contour"}});
  }

  // revolved.png: the part seen from the side, lit, tinted where it leaves the tolerance.
  {
    int IW = 900;
    double sc = IW / (zFront_ - zBack_ + 2 * pad);
    int IH = static_cast<int>(std::ceil((2 * rOut_ + 2 * pad) * sc));
    RgbImage img(IW, IH, 250);
    std::vector<double> R(static_cast<size_t>(IW), -1), dev(static_cast<size_t>(IW), 0);
    for (int c = 0; c < IW; ++c) {
      double z = zBack_ - pad + (c + 0.5) / sc;
      double best = -1;
      for (const auto& path : final)
        for (size_t k = 0; k < path.size(); ++k) {
          double z0 = static_cast<double>(path[k].X) / s, r0 = static_cast<double>(path[k].Y) / s;
          double z1 = static_cast<double>(path[(k + 1) % path.size()].X) / s,
                 r1 = static_cast<double>(path[(k + 1) % path.size()].Y) / s;
          if ((z0 <= z) == (z1 <= z)) continue;
          best = std::max(best, r0 + (z - z0) / (z1 - z0) * (r1 - r0));
        }
      R[static_cast<size_t>(c)] = best;
    }
    for (const auto& q : samples) {
      int c = static_cast<int>((q.p.z - zBack_ + pad) * sc);
      if (c >= 0 && c < IW && std::fabs(q.d) > std::fabs(dev[static_cast<size_t>(c)]))
        dev[static_cast<size_t>(c)] = q.d;
    }
    const double L[3] = {-0.35, 0.55, 0.76};  // light: from the upper left, in front
    for (int c = 0; c < IW; ++c) {
      double Rc = R[static_cast<size_t>(c)];
      if (Rc <= 0) continue;
      double Rl = c > 0 && R[static_cast<size_t>(c - 1)] > 0 ? R[static_cast<size_t>(c - 1)] : Rc;
      double Rr =
          c + 1 < IW && R[static_cast<size_t>(c + 1)] > 0 ? R[static_cast<size_t>(c + 1)] : Rc;
      double slope = (Rr - Rl) * sc / 2;  // dR/dz
      unsigned cr = 176, cg = 180, cb = 188;
      if (std::fabs(dev[static_cast<size_t>(c)]) > tol_) {
        unsigned v = 0;
        std::sscanf(deviationColour(dev[static_cast<size_t>(c)], tol_) + 1, "%x", &v);
        cr = (v >> 16) & 255, cg = (v >> 8) & 255, cb = v & 255;
      }
      int top = static_cast<int>((rOut_ + pad - Rc) * sc),
          bottom = static_cast<int>((rOut_ + pad + Rc) * sc);
      for (int y = top; y <= bottom; ++y) {
        double sy = std::clamp((rOut_ + pad - (y + 0.5) / sc) / Rc, -1.0,
                               1.0);  // sin of the angle round the axis
        double n[3] = {-slope, sy, std::sqrt(1 - sy * sy)};
        double nl = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        double lit = std::max(0.0, (n[0] * L[0] + n[1] * L[1] + n[2] * L[2]) / nl);
        double shade = 0.25 + 0.75 * lit, spec = std::pow(lit, 24) * 0.35;
        auto ch = [&](unsigned base) {
          return static_cast<uint8_t>(std::clamp(base * shade + 255 * spec, 0.0, 255.0));
        };
        img.set(c, y, ch(cr), ch(cg), ch(cb));
      }
    }
    writeFileAtomic(file("revolved.png"), encodePng(img));
    a["pictures"].push_back(
        {{"file", "revolved.png"},
         {"title", "The turned part (revolved profile), tinted where it leaves the tolerance"}});
  }
  return a;
}

}  // namespace ncvm
