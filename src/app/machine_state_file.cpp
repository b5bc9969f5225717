#include "app/machine_state_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

#include "app/machine_state.hpp"
#include "report/atomic_file.hpp"

namespace ncvm {

MachineStateFile::MachineStateFile(std::string path, double waitSeconds) : path_(std::move(path)) {
  const std::string lockPath = path_ + ".lock";
  lockFd_ = ::open(lockPath.c_str(), O_RDWR | O_CREAT | O_NOFOLLOW | O_CLOEXEC, 0666);
  if (lockFd_ < 0)
    throw std::runtime_error(fmt::format("{}: cannot create the lock file {}: {}", path_, lockPath,
                                         std::strerror(errno)));
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + std::chrono::duration<double>(std::max(0.0, waitSeconds));
  auto pause = std::chrono::milliseconds(1);
  while (::flock(lockFd_, LOCK_EX | LOCK_NB) != 0) {
    if (errno != EWOULDBLOCK && errno != EINTR) {
      int err = errno;
      ::close(lockFd_);
      throw std::runtime_error(
          fmt::format("{}: cannot lock {}: {}", path_, lockPath, std::strerror(err)));
    }
    if (Clock::now() >= deadline) {
      ::close(lockFd_);
      throw std::runtime_error(
          fmt::format("{}: in use by another run (its lock {} was held for {:g} s; --lock-wait "
                      "SECONDS waits longer)",
                      path_, lockPath, waitSeconds));
    }
    std::this_thread::sleep_for(pause);
    pause = std::min(pause * 2, std::chrono::milliseconds(50));
  }
}

MachineStateFile::~MachineStateFile() {
  if (lockFd_ >= 0) ::close(lockFd_);  // releases the lock
}

const nlohmann::json* MachineStateFile::load(const Setup& setup) {
  std::error_code ec;
  if (!std::filesystem::exists(path_, ec)) return nullptr;
  std::ifstream in(path_, std::ios::binary);
  if (!in)
    throw std::runtime_error(fmt::format("{}: cannot read: {}", path_, std::strerror(errno)));
  try {
    memory_ = nlohmann::json::parse(in);
    MachineMemory check;
    memoryFromJson(memory_, setup, check);
  } catch (const std::exception& e) {
    throw std::runtime_error(fmt::format("{}: {} (the file is left as it is)", path_, e.what()));
  }
  return &memory_;
}

void MachineStateFile::save(const std::string& text) {
  writeFileAtomic(path_, text);
}

}  // namespace ncvm
