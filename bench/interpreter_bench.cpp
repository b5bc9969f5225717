// Interpreter throughput on generated programs (docs/performance.md).
#include <benchmark/benchmark.h>
#include <fmt/format.h>

#include <string>

#include "app/session.hpp"

namespace {

std::string linearProgram(int lines) {
  std::string s = "O0001\nG90 G01 F1000.\n";
  s.reserve(static_cast<size_t>(lines) * 24);
  for (int k = 0; k < lines; ++k) s += fmt::format("X{:.3f} Y{:.3f}\n", (k % 1000) * 0.1, (k % 777) * 0.1);
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

}  // namespace

BENCHMARK_MAIN();
