#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "machine/setup.hpp"

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
