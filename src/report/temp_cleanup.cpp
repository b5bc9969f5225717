#include "report/temp_cleanup.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <signal.h>
#include <sys/syscall.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstring>
#include <filesystem>
#include <mutex>

namespace ncvm {

namespace {
// A fixed table the signal handler can read without locks or allocation. A slot is free (0),
// being filled (1) or holds a path the handler removes (2: a file, 3: a folder of files).
constexpr size_t kSlots = 256;
struct Slot {
  std::atomic<int> state{0};
  char path[PATH_MAX]{};
};
std::array<Slot, kSlots> slots;

// A folder of plain files, with system calls only (opendir and readdir may allocate).
void removeFolder(const char* path) {
  int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) return;
  alignas(8) char buf[4096];
  long n = 0;
  while ((n = ::syscall(SYS_getdents64, fd, buf, sizeof buf)) > 0) {
    for (long at = 0; at < n;) {
      // struct linux_dirent64: inode, offset, record length, type, name.
      unsigned short length = 0;
      std::memcpy(&length, buf + at + 16, sizeof length);
      const char* name = buf + at + 19;
      if (std::strcmp(name, ".") != 0 && std::strcmp(name, "..") != 0) ::unlinkat(fd, name, 0);
      at += length;
    }
  }
  ::close(fd);
  ::rmdir(path);
}

void removeAndDie(int sig) {
  for (Slot& s : slots) {
    const int state = s.state.load(std::memory_order_acquire);
    if (state == 2) ::unlink(s.path);
    if (state == 3) removeFolder(s.path);
  }
  // Die of the same signal, as without the handler: the parent sees why the run ended.
  struct sigaction dfl {};
  dfl.sa_handler = SIG_DFL;
  ::sigemptyset(&dfl.sa_mask);
  ::sigaction(sig, &dfl, nullptr);
  ::raise(sig);
}

constexpr const char* kMarker = ".ncvm-";
constexpr const char* kSuffix = ".tmp";
}  // namespace

void installTempCleanup() {
  static std::once_flag once;
  std::call_once(once, [] {
    for (int sig : {SIGINT, SIGTERM, SIGHUP, SIGPIPE}) {
      struct sigaction old {};
      ::sigaction(sig, nullptr, &old);
      if (old.sa_handler == SIG_IGN) continue;
      struct sigaction sa {};
      sa.sa_handler = removeAndDie;
      ::sigemptyset(&sa.sa_mask);
      ::sigaction(sig, &sa, nullptr);
    }
    struct sigaction ign {};
    ign.sa_handler = SIG_IGN;
    ::sigemptyset(&ign.sa_mask);
    ::sigaction(SIGXFSZ, &ign, nullptr);
  });
}

std::string tempNameFor(const std::string& target, const std::string& random) {
  return fmt::format("{}{}{}-{}{}", target, kMarker, ::getpid(), random, kSuffix);
}

void removeStaleTemps(const std::string& target) {
  namespace fs = std::filesystem;
  const fs::path t(target);
  const std::string dir = t.has_parent_path() ? t.parent_path().string() : ".";
  const std::string prefix = t.filename().string() + kMarker;
  DIR* d = ::opendir(dir.c_str());
  if (!d) return;
  while (const dirent* e = ::readdir(d)) {
    std::string_view name(e->d_name);
    if (name.size() <= prefix.size() + std::strlen(kSuffix) ||
        name.substr(0, prefix.size()) != prefix || !name.ends_with(kSuffix))
      continue;
    pid_t pid = 0;
    const char* first = name.data() + prefix.size();
    auto [end, ec] = std::from_chars(first, name.data() + name.size(), pid);
    if (ec != std::errc() || end == first || *end != '-' || pid <= 0 || pid == ::getpid()) continue;
    if (::kill(pid, 0) == 0 || errno != ESRCH) continue;  // its process still runs (or is not ours)
    // A temporary folder (--stock-out's set) goes with its files.
    if (::unlinkat(::dirfd(d), e->d_name, 0) != 0 && errno == EISDIR) {
      std::error_code ignored;
      fs::remove_all(fs::path(dir) / e->d_name, ignored);
    }
  }
  ::closedir(d);
}

int registerTemp(const std::string& path, bool folder) {
  if (path.size() >= PATH_MAX) return -1;
  for (size_t k = 0; k < kSlots; ++k) {
    int expected = 0;
    if (!slots[k].state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) continue;
    std::memcpy(slots[k].path, path.c_str(), path.size() + 1);
    slots[k].state.store(folder ? 3 : 2, std::memory_order_release);
    return static_cast<int>(k);
  }
  return -1;
}

void unregisterTemp(int slot) {
  if (slot >= 0) slots[static_cast<size_t>(slot)].state.store(0, std::memory_order_release);
}

}  // namespace ncvm
