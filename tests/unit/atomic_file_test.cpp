#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <unistd.h>

#include "report/atomic_file.hpp"

using namespace ncvm;

namespace {
std::string slurp(const std::string& p) {
  std::ifstream in(p);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}
}  // namespace

TEST(AtomicFile, ReplacesWholeFile) {
  std::string path = ::testing::TempDir() + "/atomic_a.txt";
  writeFileAtomic(path, "old");
  writeFileAtomic(path, "new contents");
  EXPECT_EQ(slurp(path), "new contents");
  std::filesystem::remove(path);
}

TEST(AtomicFile, UncommittedStreamLeavesOldFile) {
  std::string path = ::testing::TempDir() + "/atomic_b.txt";
  writeFileAtomic(path, "old");
  {
    AtomicFile f(path);
    std::fputs("half written", f.get());
    // no commit: as if the run were killed
  }
  EXPECT_EQ(slurp(path), "old");
  {
    AtomicFile f(path);
    std::fputs("complete", f.get());
    f.commit();
  }
  EXPECT_EQ(slurp(path), "complete");
  std::filesystem::remove(path);
}

TEST(AtomicFile, DeviceIsWrittenDirectly) {
  // `--trace /dev/null` must not create /dev/null.tmp.PID nor rename anything over /dev/null.
  const std::string temp = "/dev/null.tmp." + std::to_string(::getpid());
  {
    AtomicFile f("/dev/null");
    std::fputs("discarded", f.get());
    bool madeTemp = std::filesystem::exists(temp);
    ASSERT_FALSE(madeTemp);  // without the fix: leaving the scope removes the temp, no rename
    f.commit();
  }
  EXPECT_TRUE(std::filesystem::is_character_file("/dev/null"));
  EXPECT_FALSE(std::filesystem::exists(temp));
}
