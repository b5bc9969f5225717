// The report's recorder and pictures (src/report/report_recorder.hpp, toolpath_svg.hpp,
// svg_chart.hpp): what the HTML report draws is where the tool went.
#include "report/report_recorder.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "report/svg_chart.hpp"
#include "report/toolpath_svg.hpp"

namespace ncvm {
namespace {

MoveEvent line(MoveMode mode, std::array<double, 3> a, std::array<double, 3> b) {
  MoveEvent e;
  e.mode = mode;
  for (size_t k = 0; k < 3; ++k) e.start[k] = a[k], e.end[k] = b[k];
  return e;
}

TEST(ReportRecorder, ArcsAreDrawnAsChordsOnTheCircle) {
  ReportRecorder rec(defaultSetup());
  MoveEvent e = line(MoveMode::Ccw, {10, 0, 0}, {10, 0, 0});  // a full circle, R10 about 0
  e.arc = true;
  e.center = {0, 0, 0};
  rec.onMove(e);
  ASSERT_GE(rec.path().size(), 70u);  // every 5 degrees
  for (const auto& v : rec.path()) EXPECT_NEAR(std::hypot(v.p[0], v.p[1]), 10.0, 1e-4);
  EXPECT_TRUE(rec.path().front().start);
  EXPECT_NEAR(rec.path()[18].p[1], 10.0, 1e-4);  // counter-clockwise: +Y after 90 degrees
}

TEST(ReportRecorder, MovesAfterWorkZeroMovedStayWhereTheToolWent) {
  ncvm::Setup setup = defaultSetup();
  ReportRecorder rec(setup);
  rec.onWorkOrigin({{}, {100, 50, 0}});
  rec.onMove(line(MoveMode::Linear, {0, 0, 0}, {10, 0, 0}));
  // A probing macro moves work zero by X+12: the next move's X0 is X12 of the first system.
  rec.onWorkOrigin({{}, {112, 50, 0}});
  rec.onMove(line(MoveMode::Rapid, {0, 0, 0}, {0, 5, 0}));
  SkipEvent skip;
  skip.hit = true;
  skip.position = {1, 2, 3};
  rec.onSkip(skip);
  const auto& p = rec.path();
  ASSERT_EQ(p.size(), 4u);
  EXPECT_FLOAT_EQ(p[2].p[0], 12);
  EXPECT_TRUE(p[2].start);  // not joined to the first move's end
  EXPECT_EQ(p[3].kind, PathKind::Rapid);
  ASSERT_EQ(rec.probes().size(), 1u);
  EXPECT_DOUBLE_EQ(rec.probes()[0].position[0], 1);  // as the program reads it
  EXPECT_FLOAT_EQ(rec.probes()[0].drawn[0], 13);     // where it is in the picture
}

TEST(ReportRecorder, StopsAtItsSizeAndCountsWhatIsNotDrawn) {
  ReportRecorder rec(defaultSetup(), 200);
  for (int k = 0; k < 500; ++k)
    rec.onMove(line(MoveMode::Linear, {double(k), 0, 0}, {double(k + 1), 0, 0}));
  EXPECT_EQ(rec.moves(), 500u);
  EXPECT_GT(rec.movesNotDrawn(), 0u);
  EXPECT_LE(rec.path().size(), 200u);
  EXPECT_EQ(rec.path().size() - 1 + rec.movesNotDrawn(), 500u);
}

TEST(ToolpathSvg, LatheHalfSectionDrawsTheRadius) {
  ncvm::Setup setup = defaultSetup(MachineKind::Lathe);
  ASSERT_TRUE(setup.axes[0].diameter);
  ReportRecorder rec(setup);
  rec.onMove(line(MoveMode::Linear, {40, 0, 0}, {40, 0, -30}));  // X is a diameter: R20
  std::string svg = toolpathSvg(rec, setup, "mm");
  EXPECT_NE(svg.find(">Z (mm)</text>"), std::string::npos);
  EXPECT_NE(svg.find("X radius (diameter / 2) (mm)"), std::string::npos);
  // The grid is labelled up to the radius 20, not the diameter 40.
  EXPECT_NE(svg.find(">20</text>"), std::string::npos);
  EXPECT_EQ(svg.find(">40</text>"), std::string::npos);
}

TEST(SvgChart, TicksAreRound) {
  EXPECT_DOUBLE_EQ(niceStep(229.8, 5), 50);
  EXPECT_DOUBLE_EQ(niceStep(0.9, 10), 0.1);
  EXPECT_EQ(tickLabel(0.30000000000000004, 0.1), "0.3");
  EXPECT_EQ(tickLabel(-1e-12, 5), "0");
  std::string bars = barChartSvg({{"cutting", 10, "#000"}}, "time (s)",
                                 [](double v) { return std::to_string(static_cast<int>(v)); });
  EXPECT_NE(bars.find("width=\"520.00\""), std::string::npos);  // the longest bar fills the axis
}

}  // namespace
}  // namespace ncvm
