// ncvm sweep: the --vary syntax, the combinations, and the seed 002 study end to end.
#include "app/sweep.hpp"

#include <gtest/gtest.h>

#include "app/session.hpp"

namespace ncvm {
namespace {

TEST(Sweep, RangesAndLists) {
  SweepAxis a = parseSweepAxis("tool_offsets.52.d_geometry=10:30:5");
  EXPECT_EQ(a.key, "tool_offsets.52.d_geometry");
  EXPECT_EQ(a.values, (std::vector<std::string>{"10", "15", "20", "25", "30"}));
  EXPECT_EQ(parseSweepAxis("tools.1.diameter=50,63,80").values,
            (std::vector<std::string>{"50", "63", "80"}));
  EXPECT_EQ(parseSweepAxis("x=0:1:0.25").values.size(), 5u);
  EXPECT_THROW(parseSweepAxis("x=1:0:1"), SetupError);
  EXPECT_THROW(parseSweepAxis("x=0:1:0"), SetupError);
  EXPECT_THROW(parseSweepAxis("x=0:1"), SetupError);
  EXPECT_THROW(parseSweepAxis("x="), SetupError);
  EXPECT_THROW(parseSweepAxis("x=1,,2"), SetupError);
}

TEST(Sweep, EveryCombinationFirstAxisSlowest) {
  std::vector<SweepAxis> axes{parseSweepAxis("tool_offsets.52.d_geometry=1,2"),
                              parseSweepAxis("tools.1.diameter=50,63,80")};
  std::vector<std::pair<double, double>> seen;
  auto rows = runSweep(defaultSetup(), axes, "", [&](const ncvm::Setup& s, const std::string& dir) {
    EXPECT_TRUE(dir.empty());
    seen.push_back({s.toolOffsets.at(52).geometry[2], s.tools.at(1).diameter});
    return SweepRow{{}, "M30", "", nullptr, ""};
  });
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(seen[1], (std::pair<double, double>{1, 63}));
  EXPECT_EQ(seen[3], (std::pair<double, double>{2, 50}));
  EXPECT_EQ(rows[5].values, (std::vector<std::string>{"2", "80"}));
  std::string md = sweepMarkdown(axes, rows);
  EXPECT_NE(md.find("Nothing uncut: no combination."), std::string::npos);
}

// Seed 002 with full-width passes (N070 X150): a Ø80 cutter with D = 10 leaves nothing;
// D = 25 with Ø50 leaves the strips; D = 30 is the PS0041 of the paper's rule.
TEST(Sweep, FaceMillingStudy) {
  ncvm::Setup base =
      loadSetup(std::string(NCVM_SOURCE_DIR) + "/examples/face-milling-g42/face-milling-g42.toml");
  base.stock.cell = 0.5;
  std::vector<SweepAxis> axes{parseSweepAxis("tool_offsets.52.d_geometry=10,25,30"),
                              parseSweepAxis("tools.1.diameter=50,80")};
  auto rows = runSweep(base, axes, "", [](const ncvm::Setup& s, const std::string& dir) {
    Session session(s);
    session.addProgramFile(std::string(NCVM_SOURCE_DIR) +
                           "/examples/face-milling-g42/face-milling-g42-x150.nc");
    session.simulateStock(dir);
    Session::Result r = session.run(nullptr);
    SweepRow row;
    row.end = endReasonName(r.end);
    if (r.alarm) row.alarm = r.alarm->code;
    row.stock = r.stock;
    return row;
  });
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_FALSE(sweepRowClean(rows[0]));                         // D10 Ø50
  EXPECT_TRUE(sweepRowClean(rows[1]));                          // D10 Ø80
  double uncut = rows[2].stock["uncut"]["area"].get<double>();  // D25 Ø50
  EXPECT_NEAR(uncut, 15536.5, 15);
  EXPECT_EQ(rows[4].alarm, "PS0041");
  EXPECT_NE(sweepMarkdown(axes, rows).find("tools.1.diameter = 80."), std::string::npos);
}

}  // namespace
}  // namespace ncvm
