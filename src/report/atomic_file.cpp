#include "report/atomic_file.hpp"

#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace ncvm {

namespace {
std::string tempName(const std::string& path) { return fmt::format("{}.tmp.{}", path, ::getpid()); }

// True for an existing path that is not a regular file: /dev/null, a FIFO, /dev/stdout.
bool isSpecialFile(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
}


void closeAndRename(std::FILE* f, const std::string& temp, const std::string& path) {
  bool ok = std::fflush(f) == 0 && ::fsync(::fileno(f)) == 0;
  ok = (std::fclose(f) == 0) && ok;
  if (!ok || std::rename(temp.c_str(), path.c_str()) != 0) {
    std::string why = std::strerror(errno);
    std::remove(temp.c_str());
    throw std::runtime_error(fmt::format("{}: cannot write: {}", path, why));
  }
}
}  // namespace

void writeFileAtomic(const std::string& path, std::string_view data) {
  std::string temp = tempName(path);
  std::FILE* f = std::fopen(temp.c_str(), "wb");
  if (!f) throw std::runtime_error(fmt::format("{}: cannot create: {}", path, std::strerror(errno)));
  if (!data.empty() && std::fwrite(data.data(), 1, data.size(), f) != data.size()) {
    std::fclose(f);
    std::remove(temp.c_str());
    throw std::runtime_error(fmt::format("{}: cannot write", path));
  }
  closeAndRename(f, temp, path);
}

AtomicFile::AtomicFile(std::string path) : path_(std::move(path)), direct_(isSpecialFile(path_)) {
  if (!direct_) temp_ = tempName(path_);
  file_ = std::fopen(direct_ ? path_.c_str() : temp_.c_str(), "wb");
  if (!file_)
    throw std::runtime_error(fmt::format("{}: cannot create: {}", path_, std::strerror(errno)));
  constexpr size_t kBuffer = 1 << 16;
  buffer_ = std::make_unique<char[]>(kBuffer);
  std::setvbuf(file_, buffer_.get(), _IOFBF, kBuffer);
}

AtomicFile::~AtomicFile() {
  if (file_) {
    std::fclose(file_);
    if (!direct_) std::remove(temp_.c_str());
  }
}

void AtomicFile::commit() {
  std::FILE* f = file_;
  file_ = nullptr;
  if (direct_) {
    if (std::fclose(f) != 0)
      throw std::runtime_error(fmt::format("{}: cannot write: {}", path_, std::strerror(errno)));
    return;
  }
  closeAndRename(f, temp_, path_);
}

}  // namespace ncvm
