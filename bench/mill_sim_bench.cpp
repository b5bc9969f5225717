// Mill stock simulation speed (docs/performance.md): the swept-volume kernel on short ball
// segments, the same moves on a plain bounding-box kernel and on dexels for comparison, and a
// 100,000-move finishing program on a 112 x 112 mm stock with all cores.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "sim/mill_sim.hpp"
#include "sim/mill_sweep.hpp"

namespace {

using namespace ncvm;

constexpr double kSide = 112.0, kCell = 0.05;

MillTool ball6() {
  ToolSpec s;
  s.type = "ball";
  s.diameter = 6;
  return millToolFromSpec(s, 1);
}

double surface(double x, double y) {
  return -3 + 2 * std::sin(x / 10) * std::cos(y / 15);
}

// A raster finishing path: lines along X, `segment` mm moves following the surface. Along a
// line each move starts where the one before ended, as the moves of a program do.
std::vector<std::array<Point3, 2>> rasterPath(size_t moves, double segment) {
  std::vector<std::array<Point3, 2>> path;
  path.reserve(moves);
  const int perLine = static_cast<int>((kSide - 8) / segment);
  const double step = (kSide - 8) / (static_cast<double>(moves) / perLine + 1);
  for (size_t k = 0; path.size() < moves; ++k) {
    double y = 4 + step * static_cast<double>(k);
    Point3 from{4, y, surface(4, y)};
    for (int s = 1; s <= perLine && path.size() < moves; ++s) {
      double x = 4 + s * segment;
      Point3 to{x, y, surface(x, y)};
      path.push_back({from, to});
      from = to;
    }
  }
  return path;
}

// The kernel on one core, each move told (as MillSim does) whether it continues the one
// before; the stock is cut again on every iteration.
void BM_MillBallShortSegments(benchmark::State& state) {
  const MillTool t = ball6();
  const auto path = rasterPath(20000, 0.25);
  HeightField f(0, 0, kCell, static_cast<int>(kSide / kCell), static_cast<int>(kSide / kCell), 0);
  for (auto _ : state)
    for (size_t k = 0; k < path.size(); ++k) {
      bool startCut = k > 0 && continuesFrom(path[k - 1][1], path[k][0]);
      benchmark::DoNotOptimize(
          sweepLine(f, t, path[k][0], path[k][1], {}, SweepMode::Cut, startCut));
    }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * path.size()));
}
BENCHMARK(BM_MillBallShortSegments)->Unit(benchmark::kMillisecond);

// The same raster through MillSim on one core with the shank (20 mm flutes) and a Ø40 holder
// 45 mm above the tip checked on every move, and a rapid at a safe height after every row:
// what a setup that describes the whole tool costs.
void BM_MillBallWithHolder(benchmark::State& state) {
  ToolSpec spec;
  spec.type = "ball";
  spec.diameter = 6;
  spec.fluteLength = 20;
  spec.length = 80;
  spec.holderLength = 35;
  spec.holderDiameter = 40;
  const MillTool t = millToolFromSpec(spec, 1);
  const auto path = rasterPath(20000, 0.25);
  const int n = static_cast<int>(kSide / kCell);
  for (auto _ : state) {
    MillSim sim(HeightField(0, 0, kCell, n, n, 0), 1);
    sim.setTool(&t);
    for (size_t k = 0; k < path.size(); ++k) {
      if (k > 0 && !continuesFrom(path[k - 1][1], path[k][0])) {
        Point3 up{path[k - 1][1][0], path[k - 1][1][1], 10}, over{path[k][0][0], path[k][0][1], 10};
        sim.line(path[k - 1][1], up, true, 0);
        sim.line(up, over, true, 0);
        sim.line(over, path[k][0], true, 0);
      }
      sim.line(path[k][0], path[k][1], false, 0);
    }
    benchmark::DoNotOptimize(sim.contacts().size());
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * path.size()));
}
BENCHMARK(BM_MillBallWithHolder)->Unit(benchmark::kMillisecond);

// Arcs as CAM arc fitting writes them: 2 mm G02/G03 pieces of concentric circles (radius 5
// to 50 mm) around the stock's centre, Ø6 ball at constant Z, one core.
void BM_MillBallArcs(benchmark::State& state) {
  const MillTool t = ball6();
  struct Arc {
    double radius, a0, sweep;
  };
  std::vector<Arc> arcs;
  for (double ra = 5; arcs.size() < 5000; ra += 0.3) {
    int n = static_cast<int>(std::ceil(2 * M_PI * ra / 2.0));
    for (int k = 0; k < n && arcs.size() < 5000; ++k)
      arcs.push_back({ra, 2 * M_PI * k / n, 2 * M_PI / n});
  }
  HeightField f(0, 0, kCell, static_cast<int>(kSide / kCell), static_cast<int>(kSide / kCell), 0);
  for (auto _ : state)
    for (const Arc& a : arcs)
      benchmark::DoNotOptimize(sweepArcXY(f, t, kSide / 2, kSide / 2, a.radius, a.a0, a.sweep, -1));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * arcs.size()));
}
BENCHMARK(BM_MillBallArcs)->Unit(benchmark::kMillisecond);

// The plain kernel of the issue: every cell of the move's bounding box, double precision,
// the envelope found by placing the ball at the cell's nearest point of the centre line.
float plainBoxKernel(HeightField& f, double r, const Point3& a, const Point3& b) {
  int ilo, ihi, jlo, jhi;
  f.columnsWithin(std::min(a[0], b[0]) - r, std::max(a[0], b[0]) + r, ilo, ihi);
  f.rowsWithin(std::min(a[1], b[1]) - r, std::max(a[1], b[1]) + r, jlo, jhi);
  const double dx = b[0] - a[0], dy = b[1] - a[1], dz = b[2] - a[2];
  const double l2 = dx * dx + dy * dy + dz * dz;
  float pen = 0;
  for (int j = jlo; j < jhi; ++j)
    for (int i = ilo; i < ihi; ++i) {
      double qx = f.cellX(i) - a[0], qy = f.cellY(j) - a[1];
      double best = 1e30;
      // Three candidates: both end spheres and the sphere at the projected point.
      double ts[3] = {0, 1, std::clamp((qx * dx + qy * dy) / l2, 0.0, 1.0)};
      for (double t : ts) {
        double ex = qx - t * dx, ey = qy - t * dy, d2 = ex * ex + ey * ey;
        if (d2 <= r * r) best = std::min(best, a[2] + t * dz + r - std::sqrt(r * r - d2));
      }
      float old = f.at(i, j), nz = std::min(old, static_cast<float>(best));
      pen = std::max(pen, old - nz);
      f.at(i, j) = nz;
    }
  return pen;
}

void BM_MillPlainBoxKernel(benchmark::State& state) {
  const auto path = rasterPath(20000, 0.25);
  HeightField f(0, 0, kCell, static_cast<int>(kSide / kCell), static_cast<int>(kSide / kCell), 0);
  for (auto _ : state)
    for (const auto& m : path) benchmark::DoNotOptimize(plainBoxKernel(f, 3.0, m[0], m[1]));
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * path.size()));
}
BENCHMARK(BM_MillPlainBoxKernel)->Unit(benchmark::kMillisecond);

// Dexels along Z: each cell keeps a list of material intervals; a 3-axis cut from above
// trims the top interval. Same moves, same envelope (the exact kernel's), general storage.
struct Dexels {
  struct Interval {
    float lo, hi;
  };
  int nx, ny;
  std::vector<std::vector<Interval>> cells;
  Dexels(int x, int y, float bottom, float top)
      : nx(x), ny(y), cells(size_t(x) * size_t(y), std::vector<Interval>{{bottom, top}}) {}
  size_t bytes() const {
    size_t b = cells.size() * sizeof(std::vector<Interval>);
    for (const auto& c : cells) b += c.capacity() * sizeof(Interval);
    return b;
  }
};

void BM_MillDexels(benchmark::State& state) {
  const MillTool t = ball6();
  const auto path = rasterPath(20000, 0.25);
  const int n = static_cast<int>(kSide / kCell);
  Dexels d(n, n, -20, 0);
  // The envelope of each move comes from a scratch field over its footprint (cost counted).
  HeightField scratch(0, 0, kCell, n, n, 1e9f);
  for (auto _ : state)
    for (const auto& m : path) {
      int ilo, ihi, jlo, jhi;
      scratch.columnsWithin(std::min(m[0][0], m[1][0]) - 3, std::max(m[0][0], m[1][0]) + 3, ilo,
                            ihi);
      scratch.rowsWithin(std::min(m[0][1], m[1][1]) - 3, std::max(m[0][1], m[1][1]) + 3, jlo, jhi);
      sweepLine(scratch, t, m[0], m[1]);
      for (int j = jlo; j < jhi; ++j)
        for (int i = ilo; i < ihi; ++i) {
          float& env = scratch.at(i, j);
          if (env < 1e9f) {
            auto& c = d.cells[size_t(j) * size_t(n) + size_t(i)];
            while (!c.empty() && c.back().lo >= env) c.pop_back();
            if (!c.empty()) c.back().hi = std::min(c.back().hi, env);
            env = 1e9f;
          }
        }
    }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * path.size()));
  state.counters["bytes_per_cell"] = static_cast<double>(d.bytes()) / (double(n) * n);
}
BENCHMARK(BM_MillDexels)->Unit(benchmark::kMillisecond);

// 100,000 finishing moves on a 112 x 112 mm stock at 0.05 mm: the batch runner on all
// cores (Arg = threads; 0 = all), wall time.
void BM_MillFinishing100k(benchmark::State& state) {
  const MillTool t = ball6();
  const auto path = rasterPath(100000, 0.28);
  const int n = static_cast<int>(kSide / kCell);
  for (auto _ : state) {
    MillSim sim(HeightField(0, 0, kCell, n, n, 0), static_cast<int>(state.range(0)));
    sim.setTool(&t);
    for (const auto& m : path) sim.line(m[0], m[1], false, 0);
    benchmark::DoNotOptimize(sim.field().data().data());
    state.counters["bytes_per_cell"] = static_cast<double>(sim.field().bytes()) / (double(n) * n);
  }
  state.SetItemsProcessed(static_cast<int64_t>(state.iterations() * path.size()));
}
BENCHMARK(BM_MillFinishing100k)->Arg(1)->Arg(0)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
