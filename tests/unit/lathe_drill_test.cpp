// Lathe drilling cycles (G83/G87) as a property over many holes: whatever the depth, the peck
// Q, the peck type (5101#2 RTR) and the drilling axis, every feed goes deeper by at most Q,
// the feeds end exactly at the bottom, the number of feeds is ceil(depth / Q), and the tool
// ends at the initial level (system A has no G99).
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "app/session.hpp"

using namespace ncvm;

namespace {
struct Moves final : EventSink {
  std::vector<MoveEvent> all;
  void onMove(const MoveEvent& e) override { all.push_back(e); }
};
}  // namespace

TEST(LatheDrill, PecksNeverPassQAndEndAtTheBottom) {
  std::mt19937 rng(4);
  std::uniform_int_distribution<int> depthUm(500, 60000), qUm(300, 9000), rUm(500, 5000);
  for (int run = 0; run < 120; ++run) {
    const bool side = run % 2 == 1, deep = run % 4 >= 2;
    const double depth = depthUm(rng) / 1000.0, q = qUm(rng) / 1000.0, r = rUm(rng) / 1000.0;
    // Face: from Z10, R level 10 - r, bottom below it. Side: from X80 (radius 40).
    const double initial = side ? 40.0 : 10.0, rLevel = initial - r, bottom = rLevel - depth;
    std::string prog = side ? fmt::format(
                                  "O1\nG21 G99\nS500 M03\nG00 X80. Z-10.\n"
                                  "G87 X{:.3f} R{:.3f} Q{:.3f} F0.1\nG80\nM30\n",
                                  2 * bottom, -r, q)
                            : fmt::format(
                                  "O1\nG21 G99\nS500 M03\nG00 X0 Z10.\n"
                                  "G83 Z{:.3f} R{:.3f} Q{:.3f} F0.1\nG80\nM30\n",
                                  bottom, -r, q);
    ncvm::Setup setup = defaultSetup(MachineKind::Lathe);
    if (deep) applySetting(setup, "5101#2=1");
    Session s(setup);
    s.addProgramText(prog, "t.nc");
    Moves sink;
    auto res = s.run(&sink);
    ASSERT_FALSE(res.alarm) << prog << res.alarm->text;
    const size_t axis = side ? 0 : 2;
    auto level = [&](const MoveEvent& m) { return side ? m.end[axis] / 2.0 : m.end[axis]; };
    double deepest = rLevel;
    int feeds = 0;
    for (size_t i = 1; i < sink.all.size(); ++i) {
      const MoveEvent& m = sink.all[i];
      if (m.mode != MoveMode::Linear) continue;
      ++feeds;
      double at = level(m);
      EXPECT_LT(at, deepest + 1e-9) << prog;      // always deeper than before
      EXPECT_LE(deepest - at, q + 1e-6) << prog;  // by at most one peck
      EXPECT_GE(at, bottom - 1e-6) << prog;       // never below the bottom
      deepest = at;
    }
    EXPECT_NEAR(deepest, bottom, 1e-6) << prog;
    EXPECT_EQ(feeds, static_cast<int>(std::ceil(depth / q - 1e-9))) << prog;
    EXPECT_NEAR(level(sink.all.back()), initial, 1e-6) << prog;
  }
}
