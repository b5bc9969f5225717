// Lathe stock simulation throughput: moves per second on the exact half-profile
// (docs/performance.md). Every move of these paths removes material.
#include <benchmark/benchmark.h>

#include <cmath>
#include <vector>

#include "sim/lathe_stock.hpp"

namespace {

ncvm::Setup bar() {
  ncvm::Setup s = ncvm::defaultSetup(ncvm::MachineKind::Lathe);
  s.stock.present = true;
  s.stock.diameter = 50;
  s.stock.length = 100;
  return s;
}

ncvm::ToolSpec insert(double nose) {
  ncvm::ToolSpec t{"insert"};
  t.noseRadius = nose;
  t.tip = 3;
  return t;
}

// Profiling passes of short segments (step mm along Z) with a wavy depth, 0.5 mm deeper
// each pass: what a CAM finishing or roughing program on a lathe looks like.
std::vector<ncvm::lsim::Pt> wavyPasses(double step, int moves) {
  std::vector<ncvm::lsim::Pt> pts;
  int perPass = static_cast<int>(90 / step);
  for (int k = 0; pts.size() < static_cast<size_t>(moves) + 1; ++k) {
    int pass = k / perPass, i = k % perPass;
    double z = -i * step, r = 24.5 - 0.5 * pass + 0.05 * std::sin(z * 2);
    pts.push_back({r, z});
  }
  return pts;
}

void BM_LatheShortMoves(benchmark::State& state) {
  double step = static_cast<double>(state.range(0)) / 1000;  // mm
  auto pts = wavyPasses(step, 20000);
  for (auto _ : state) {
    state.PauseTiming();
    ncvm::LatheStock st(bar());
    st.selectTool(insert(0.4));
    state.ResumeTiming();
    // Through the event interface, as in a run: X is a diameter.
    ncvm::MoveEvent e;
    e.mode = ncvm::MoveMode::Linear;
    for (size_t k = 1; k < pts.size(); ++k) {
      e.start[0] = 2 * pts[k - 1].r, e.start[2] = pts[k - 1].z;
      e.end[0] = 2 * pts[k].r, e.end[2] = pts[k].z;
      st.onMove(e);
    }
    benchmark::DoNotOptimize(st.area());
  }
  state.SetItemsProcessed(state.iterations() * static_cast<int64_t>(pts.size() - 1));
}
// Segment length 0.05, 0.1 and 0.5 mm.
BENCHMARK(BM_LatheShortMoves)->Arg(50)->Arg(100)->Arg(500)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
