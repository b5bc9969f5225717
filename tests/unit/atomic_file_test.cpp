#include "report/atomic_file.hpp"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "report/temp_cleanup.hpp"

using namespace ncvm;

namespace {
// A fresh folder per test: the tests list what a write leaves beside its target.
std::string freshFolder(const std::string& name) {
  const std::string dir =
      ::testing::TempDir() + "/atomic_" + name + "_" + std::to_string(::getpid());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

size_t entries(const std::string& dir) {
  size_t n = 0;
  for ([[maybe_unused]] const auto& e : std::filesystem::directory_iterator(dir)) ++n;
  return n;
}

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

TEST(AtomicFile, FifoIsWrittenDirectlyAndStaysAFifo) {
  const std::string dir = freshFolder("fifo");
  const std::string fifo = dir + "/pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  // A reader first, so that opening the FIFO for writing does not wait.
  int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  writeFileAtomic(fifo, "through the pipe");
  char buf[64] = {};
  ssize_t got = ::read(reader, buf, sizeof buf - 1);
  ::close(reader);
  EXPECT_EQ(std::string(buf, got > 0 ? static_cast<size_t>(got) : 0), "through the pipe");
  EXPECT_TRUE(std::filesystem::is_fifo(fifo));  // not replaced by a regular file
  EXPECT_EQ(entries(dir), 1u);
  std::filesystem::remove_all(dir);
}

TEST(AtomicFile, APlantedSymlinkIsNeverWrittenThrough) {
  // The old temporary name, PATH.tmp.PID, could be predicted: a symlink planted there made
  // the write go into its target. Now the temporary is created exclusively, under a random
  // name, without following a symlink.
  const std::string dir = freshFolder("symlink");
  const std::string victim = dir + "/victim", out = dir + "/out.json";
  writeFileAtomic(victim, "precious");
  std::filesystem::create_symlink(victim, out + ".tmp." + std::to_string(::getpid()));
  writeFileAtomic(out, "output");
  EXPECT_EQ(slurp(victim), "precious");
  EXPECT_EQ(slurp(out), "output");
  EXPECT_EQ(entries(dir), 3u);  // victim, out.json, the planted link: no temporary left
  std::filesystem::remove_all(dir);
}

TEST(AtomicFile, TemporariesAreUnpredictableAndExclusive) {
  const std::string dir = freshFolder("names");
  const std::string out = dir + "/trace.jsonl";
  AtomicFile a(out), b(out);
  std::vector<std::string> names;
  for (const auto& e : std::filesystem::directory_iterator(dir))
    names.push_back(e.path().filename().string());
  ASSERT_EQ(names.size(), 2u);
  EXPECT_NE(names[0], names[1]);
  for (const auto& n : names)
    EXPECT_EQ(n.rfind("trace.jsonl.ncvm-" + std::to_string(::getpid()) + "-", 0), 0u) << n;
}

TEST(AtomicFile, StaleTemporariesOfDeadProcessesAreRemoved) {
  const std::string dir = freshFolder("stale");
  const std::string out = dir + "/state.json";
  pid_t child = ::fork();
  if (child == 0) ::_exit(0);
  ASSERT_GT(child, 0);
  ::waitpid(child, nullptr, 0);  // a process that no longer exists
  const std::string deadName = out + ".ncvm-" + std::to_string(child) + "-0123456789abcdef.tmp";
  writeFileAtomic(deadName, "left by a killed run");
  // One of a process that still runs (this test's parent) and an unrelated file stay.
  const std::string live = out + ".ncvm-" + std::to_string(::getppid()) + "-00.tmp";
  writeFileAtomic(live, "another run's");
  writeFileAtomic(dir + "/state.json.keep", "mine");
  writeFileAtomic(out, "new");
  EXPECT_FALSE(std::filesystem::exists(deadName));
  EXPECT_TRUE(std::filesystem::exists(live));
  EXPECT_TRUE(std::filesystem::exists(dir + "/state.json.keep"));
  EXPECT_EQ(slurp(out), "new");
  std::filesystem::remove_all(dir);
}

TEST(TempCleanup, ASignalRemovesTheRegisteredFilesAndFolders) {
  const std::string dir = freshFolder("signal");
  const std::string file = dir + "/trace.jsonl.ncvm-1-aa.tmp",
                    folder = dir + "/stock.ncvm-1-bb.tmp";
  pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    installTempCleanup();
    std::filesystem::create_directories(folder);
    for (int k = 0; k < 300; ++k)
      std::ofstream(folder + "/picture" + std::to_string(k) + ".png") << k;
    std::ofstream(file) << "half a trace";
    registerTemp(file);
    registerTemp(folder, true);
    ::raise(SIGTERM);
    ::_exit(0);  // not reached: the handler dies of the signal
  }
  int status = 0;
  ::waitpid(child, &status, 0);
  EXPECT_TRUE(WIFSIGNALED(status) && WTERMSIG(status) == SIGTERM) << status;
  EXPECT_EQ(entries(dir), 0u);
  std::filesystem::remove_all(dir);
}
