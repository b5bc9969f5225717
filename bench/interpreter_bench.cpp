// Interpreter throughput on generated programs (docs/performance.md).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <cmath>
#include <string>

#include "app/session.hpp"

namespace {

std::string linearProgram(int lines) {
  std::string s = "O0001\nG90 G01 F1000.\n";
  s.reserve(static_cast<size_t>(lines) * 24);
  for (int k = 0; k < lines; ++k)
    s += fmt::format("X{:.3f} Y{:.3f}\n", (k % 1000) * 0.1, (k % 777) * 0.1);
  s += "M30\n";
  return s;
}

const char* kWhileLoop =
    "O0002\n#1=0\n#2=0\nWHILE[#1LT[#100]]DO1\n#2=#2+SIN[#1]*COS[#1]\n#1=#1+1\nEND1\nM30\n";

void BM_LinearMoves(benchmark::State& state) {
  std::string text = linearProgram(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    ncvm::Session s(ncvm::defaultSetup());
    s.addProgramText(text, "lin.nc");
    auto r = s.run(nullptr);
    benchmark::DoNotOptimize(r.stats.blocks);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_LinearMoves)->Arg(100000)->Unit(benchmark::kMillisecond);

void BM_WhileLoop(benchmark::State& state) {
  ncvm::Setup setup = ncvm::defaultSetup();
  setup.initialVars[100] = static_cast<double>(state.range(0));
  for (auto _ : state) {
    ncvm::Session s(setup);
    s.addProgramText(kWhileLoop, "loop.nc");
    auto r = s.run(nullptr);
    benchmark::DoNotOptimize(r.stats.blocks);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
BENCHMARK(BM_WhileLoop)->Arg(100000)->Unit(benchmark::kMillisecond);

// A CAM finishing program: a raster over a wavy surface, X, Y and Z on every line (short
// segments, small direction changes), as bench/gen_programs.py writes linear_1m.nc; one block
// in 25 is an arc of R5 (G2 and G3 in turn, a helix where Z changes), as CAM arc fitting
// writes them.
std::string camProgram(int lines) {
  std::string s = "O0003\nG90 G21 G17 G94\nT1 M06\nS8000 M03\nG00 X0 Y0 Z5.\nG01 Z0 F3000.\n";
  s.reserve(static_cast<size_t>(lines) * 28);
  const int perRow = 500;
  for (int k = 0; k < lines; ++k) {
    int row = k / perRow, col = k % perRow;
    double x = (row % 2 ? perRow - col : col) * 0.2, y = row * 0.5;
    double z = -1.0 + 0.5 * std::sin(x * 0.05) * std::cos(y * 0.07);
    if (col % 25 == 12)
      s += fmt::format("G{} X{:.3f} Y{:.3f} Z{:.3f} R5.\n", (k / 25) % 2 ? 2 : 3, x, y, z);
    else if (col % 25 == 13)
      s += fmt::format("G1 X{:.3f} Y{:.3f} Z{:.3f}\n", x, y, z);
    else
      s += fmt::format("X{:.3f} Y{:.3f} Z{:.3f}\n", x, y, z);
  }
  s += "G00 Z50.\nM05\nM30\n";
  return s;
}

// The same 100,000-block program with the cycle-time model off (no stage), in its simple
// mode, and in its dynamic mode (look-ahead planning with the 0i-MF defaults), on the
// control's thread as in `ncvm run`.
void camRun(benchmark::State& state, bool timing, bool dynamic) {
  std::string text = camProgram(static_cast<int>(state.range(0)));
  ncvm::Setup setup = ncvm::defaultSetup();
  setup.timing.dynamic = dynamic;
  for (auto _ : state) {
    ncvm::Session s(setup);
    s.setTiming(timing);
    s.addProgramText(text, "cam.nc");
    auto r = s.run(nullptr);
    benchmark::DoNotOptimize(r.stats.blocks);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}
void BM_CamNoTiming(benchmark::State& state) {
  camRun(state, false, false);
}
void BM_CamTimingSimple(benchmark::State& state) {
  camRun(state, true, false);
}
void BM_CamTimingDynamic(benchmark::State& state) {
  camRun(state, true, true);
}
BENCHMARK(BM_CamNoTiming)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CamTimingSimple)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CamTimingDynamic)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CamNoTiming)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CamTimingSimple)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_CamTimingDynamic)->Arg(100000)->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
