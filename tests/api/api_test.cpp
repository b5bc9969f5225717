// The public C++ API (include/ncvm) through libncvm.so itself: what a program that embeds
// ncvm sees (only the exported names link).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <ncvm/ncvm.hpp>
#include <string>
#include <vector>

namespace {

using namespace ncvm::api;

struct Recorder final : EventHandler {
  void onMove(const Move& m) override {
    moves.push_back(m);
    files.emplace_back(m.at.file);
  }
  void onTool(const ToolSelect& t) override { tools.push_back(t.tool); }
  void onMessage(const Message& m) override { messages.emplace_back(m.text); }
  void onAlarm(const AlarmEvent& a) override { alarms.emplace_back(a.code); }
  std::vector<Move> moves;
  std::vector<std::string> files, messages, alarms;
  std::vector<int> tools;
};

std::string sourceFile(const std::string& rel) {
  return std::string(NCVM_SOURCE_DIR) + "/" + rel;
}

TEST(Api, RunsProgramTextAndReportsTheMovesInOrder) {
  Job job;
  job.addProgramText("%\nO1\nT1 M6\nG90 G0 X10. Y0\nG1 X20. F100.\nG2 X30. Y10. R10.\nM30\n%\n",
                     "part");
  Recorder rec;
  RunResult r = job.run(&rec);
  EXPECT_EQ(r.end, EndReason::M30);
  EXPECT_EQ(endReasonName(r.end), "M30");
  EXPECT_FALSE(r.alarm);
  ASSERT_EQ(rec.moves.size(), 3u);
  EXPECT_EQ(rec.moves[0].kind, MoveKind::Rapid);
  EXPECT_EQ(rec.moves[1].kind, MoveKind::Linear);
  EXPECT_EQ(rec.moves[2].kind, MoveKind::ArcCw);
  EXPECT_DOUBLE_EQ(rec.moves[1].start[0], 10);
  EXPECT_DOUBLE_EQ(rec.moves[1].end[0], 20);
  EXPECT_DOUBLE_EQ(rec.moves[1].feed, 100);
  EXPECT_NEAR(rec.moves[1].time, 10.0 / 100 * 60, 1e-9);  // 10 mm at 100 mm/min
  EXPECT_EQ(rec.moves[2].at.line, 6u);
  EXPECT_EQ(rec.files[0], "part");
  EXPECT_EQ(rec.tools, (std::vector<int>{1, 1}));  // T1 selects, M6 changes
  EXPECT_EQ(r.stats.moves, 3u);
  EXPECT_NEAR(r.stats.feedLength, 10 + 10 * 3.14159265358979 / 2, 1e-6);
  EXPECT_NE(r.stateJson.find("\"end\""), std::string::npos);
}

TEST(Api, AnAlarmIsAResultWithItsPlace) {
  Job job;
  job.addProgramText("%\nO1\nG0 X1\n#1=1/0\nM30\n%\n", "div.nc");
  Recorder rec;
  RunResult r = job.run(&rec);
  EXPECT_EQ(r.end, EndReason::Alarm);
  ASSERT_TRUE(r.alarm);
  EXPECT_EQ(r.alarm->code, "PS0112");
  EXPECT_EQ(r.alarm->where.file, "div.nc");
  EXPECT_EQ(r.alarm->where.line, 4);
  EXPECT_GT(r.alarm->where.column, 0);
  EXPECT_EQ(rec.alarms, std::vector<std::string>{"PS0112"});
}

TEST(Api, SettingsApplyInOrderAndBadOnesThrow) {
  Job job;
  // Without DPI, X1 is 1 least increment (0.001 mm); with DPI=1 it is 1 mm.
  job.set("DPI=1");
  job.addProgramText("G0 X1\nM30\n");
  Recorder rec;
  job.run(&rec);
  ASSERT_EQ(rec.moves.size(), 1u);
  EXPECT_DOUBLE_EQ(rec.moves[0].end[0], 1.0);

  Job plain;
  plain.addProgramText("G0 X1\nM30\n");
  Recorder rec2;
  plain.run(&rec2);
  ASSERT_EQ(rec2.moves.size(), 1u);
  EXPECT_DOUBLE_EQ(rec2.moves[0].end[0], 0.001);

  EXPECT_THROW(job.set("no_such_section.key=1"), Error);
  EXPECT_THROW(job.loadSetup("/nonexistent/setup.toml"), Error);
  EXPECT_THROW(job.loadPreset("no-such-preset"), Error);
  EXPECT_THROW(job.addProgramFile("/nonexistent/part.nc"), Error);
}

TEST(Api, PresetsAndFilesFromTheDataFolder) {
  EXPECT_FALSE(dataFolder().empty());
  Job job;
  job.loadPreset("fanuc-0i-tf");  // a lathe
  job.addProgramFile(sourceFile("examples/lathe-cycles/g71-g70-rough-turning.nc"));
  RunResult r = job.run();
  EXPECT_FALSE(r.alarm) << r.alarm->code << " " << r.alarm->message;
  // A lathe's modal group 2 is G96/G97 (a mill's the plane, G17).
  EXPECT_NE(r.stateJson.find("\"2\": 97.0"), std::string::npos) << r.stateJson.substr(0, 600);
}

TEST(Api, FoldersServeCallsAndTheBundledMacrosCanBeLeftOut) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "ncvm-api-test-lib";
  fs::create_directories(dir);
  std::ofstream(dir / "O9100.nc") << "%\nO9100\n#500=#1\nM99\n%\n";
  Job job;
  job.addProgramText("G65 P9100 A7.\nM30\n");
  job.addFolder(dir.string());
  RunResult r = job.run();
  EXPECT_FALSE(r.alarm);
  EXPECT_NE(r.stateJson.find("\"#500\": 7"), std::string::npos) << r.stateJson.substr(0, 2000);

  Job none;
  none.addProgramText("G65 P9100 A7.\nM30\n");
  none.useBundledMacros(false);
  RunResult missing = none.run();
  ASSERT_TRUE(missing.alarm);
  EXPECT_EQ(missing.alarm->code, "PS0076");  // program not found
  fs::remove_all(dir);
  EXPECT_THROW(none.addFolder(dir.string()), Error);
}

TEST(Api, CheckFindsWithoutRunning) {
  Job job;
  job.addProgramText("G1 X1. X2. F100\nGOTO 99\nM30\n", "c.nc");
  CheckResult c = job.check();
  bool twice = false;
  for (const auto& w : c.warnings) twice |= w.code == "W002" && w.where.line == 1;
  EXPECT_TRUE(twice) << c.json;
  EXPECT_NE(c.json.find("W002"), std::string::npos);
}

TEST(Api, WhatLoadingFindsIsAWarningWithoutCode) {
  Job job;
  job.addProgramText("%\nO1\nG0 X1.\nM30\n%\nG0 X5.\n", "w.nc");
  RunResult r = job.run();
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_EQ(r.warnings[0].code, "");
  EXPECT_NE(r.warnings[0].message.find("after the closing '%'"), std::string::npos)
      << r.warnings[0].message;
}

TEST(Api, VersionIsTheCommandsVersion) {
  EXPECT_EQ(version().rfind(NCVM_PROJECT_VERSION, 0), 0u) << version();
}

}  // namespace
