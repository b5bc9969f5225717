#include "machine/setup.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

#include "machine/setup_keys.hpp"

using namespace ncvm;

TEST(Setup, DefaultsAreAThreeAxisMill) {
  ncvm::Setup s = defaultSetup();
  EXPECT_EQ(s.kind, MachineKind::Mill);
  EXPECT_GE(s.axisSlot('Z'), 0);
  EXPECT_LT(s.axisSlot('A'), 0);
  EXPECT_FALSE(s.dpi());
}

TEST(Setup, SetAcceptsParametersAliasesAndKeys) {
  ncvm::Setup s = defaultSetup();
  applySetting(s, "3401#0=1");
  EXPECT_TRUE(s.dpi());
  applySetting(s, "NAT=1");
  EXPECT_TRUE(s.nat());
  applySetting(s, "block_skip.2=true");
  EXPECT_TRUE(s.blockSkip[2]);
  applySetting(s, "limits.max_blocks=50");
  EXPECT_EQ(s.limits.maxBlocks, 50u);
  applySetting(s, "machine.kind=lathe");
  EXPECT_EQ(s.kind, MachineKind::Lathe);
  EXPECT_TRUE(s.axes[0].diameter);
}

TEST(Setup, UnknownKeyIsASetupErrorWithKey) {
  ncvm::Setup s = defaultSetup();
  try {
    applySetting(s, "machine.colour=red");
    FAIL();
  } catch (const SetupError& e) {
    EXPECT_EQ(e.key, "machine.colour");
  }
  EXPECT_THROW(applySetting(s, "9999999=1"), SetupError);
}

TEST(Setup, TomlFileWithLineOfBadKey) {
  std::string path = ::testing::TempDir() + "/bad_setup.toml";
  {
    std::ofstream f(path);
    f << "[machine]\nkind = \"lathe\"\n\n[limits]\nmax_blocks = -5\n";
  }
  try {
    loadSetup(path);
    FAIL();
  } catch (const SetupError& e) {
    EXPECT_EQ(e.key, "limits.max_blocks");
    EXPECT_EQ(e.line, 5);
  }
  std::remove(path.c_str());
}

TEST(Setup, StockAndTargetSections) {
  ncvm::Setup s = defaultSetup(MachineKind::Lathe);
  applySetting(s, "stock.diameter=80");
  applySetting(s, "stock.length=120.5");
  applySetting(s, "stock.front_z=0.5");
  applySetting(s, "stock.bore_diameter=20");
  applySetting(s, "target.blocks=N60..N100");
  applySetting(s, "target.shift=[0.03,0.01]");
  applySetting(s, "target.tolerance=0.005");
  EXPECT_TRUE(s.stock.present);
  EXPECT_DOUBLE_EQ(s.stock.diameter, 80);
  EXPECT_DOUBLE_EQ(s.stock.length, 120.5);
  EXPECT_DOUBLE_EQ(s.stock.frontZ, 0.5);
  EXPECT_DOUBLE_EQ(s.stock.boreDiameter, 20);
  EXPECT_EQ(s.target.fromN, 60);
  EXPECT_EQ(s.target.toN, 100);
  EXPECT_DOUBLE_EQ(s.target.shift[0], 0.03);
  EXPECT_DOUBLE_EQ(s.target.tolerance, 0.005);
  applySetting(s, "target.blocks=200");
  EXPECT_EQ(s.target.fromN, 200);
  EXPECT_EQ(s.target.toN, 200);
  EXPECT_THROW(applySetting(s, "target.blocks=N100..N60"), SetupError);
  EXPECT_THROW(applySetting(s, "target.blocks=N1x"), SetupError);
  EXPECT_THROW(applySetting(s, "stock.diameter=-1"), SetupError);
  EXPECT_THROW(applySetting(s, "stock.colour=red"), SetupError);
  EXPECT_THROW(applySetting(s, "stock.frame=G99"), SetupError);
  EXPECT_THROW(applySetting(s, "stock.frame=G54"), SetupError);  // the stock sits on the machine
  applySetting(s, "stock.frame=program");
  EXPECT_EQ(s.stock.frame, "program");

  ncvm::Setup m = defaultSetup();
  applySetting(m, "stock.min=[-50,-50,-20]");
  applySetting(m, "stock.max=[50,50,0]");
  applySetting(m, "stock.cell=0.05");
  applySetting(m, "stock.frame=machine");
  applySetting(m, "target.face_z=-0.5");
  ASSERT_EQ(m.stock.min.size(), 3u);
  EXPECT_DOUBLE_EQ(m.stock.max[0], 50);
  EXPECT_DOUBLE_EQ(m.stock.cell, 0.05);
  EXPECT_EQ(m.stock.frame, "machine");
  ASSERT_TRUE(m.target.faceZ.has_value());
  EXPECT_DOUBLE_EQ(*m.target.faceZ, -0.5);
  EXPECT_THROW(applySetting(m, "stock.min=[1,2]"), SetupError);
}

TEST(Setup, TargetFilesAreFoundBesideTheSetup) {
  std::string dir = ::testing::TempDir();
  std::string path = dir + "/target_setup.toml";
  {
    std::ofstream f(path);
    f << "[machine]\nkind = \"lathe\"\n[target]\npolyline = \"contour.csv\"\n[probe]\nuse_stock = "
         "true\n";
  }
  ncvm::Setup s = loadSetup(path);
  EXPECT_EQ(s.target.polyline, (std::filesystem::path(dir) / "contour.csv").string());
  EXPECT_TRUE(s.probe.useStock);
  std::remove(path.c_str());
}

// The names behind "did you mean": each one is a key the setup reads (no suggestion of a
// key that would then be refused as unknown).
TEST(SetupKeys, EverySuggestedKeyIsAccepted) {
  const char* values[] = {"1",      "4",   "true",    "mill",  "0i-F",    "A",
                          "IS-B",   "mm",  "flat",    "box",   "machine", "sharp",
                          "simple", "N10", "[0,0,0]", "[0,0]", "x.txt",   "ball_bottom"};
  for (std::string key : setupKeyNames()) {
    for (auto p = key.find(".X"); p != std::string::npos; p = key.find(".X"))
      key.replace(p, 2, ".Y");
    for (auto p = key.find(".N"); p != std::string::npos; p = key.find(".N"))
      key.replace(p, 2, ".1");
    bool accepted = false;
    std::string last;
    for (const char* v : values) {
      ncvm::Setup s = defaultSetup();
      try {
        applySetting(s, key + "=" + v);
        accepted = true;
        break;
      } catch (const SetupError& e) {
        last = e.what();
      }
    }
    EXPECT_TRUE(accepted) << key << ": " << last;
  }
}

TEST(SetupKeys, NearestKeyKeepsTheAxisAndNumber) {
  EXPECT_EQ(nearestSetupKey("machin.kind"), "machine.kind");
  EXPECT_EQ(nearestSetupKey("axes.Z.rapd"), "axes.Z.rapid");
  EXPECT_EQ(nearestSetupKey("tool_offsets.52.d_geometri"), "tool_offsets.52.d_geometry");
  EXPECT_EQ(nearestSetupKey("completely.different"), std::nullopt);
}
