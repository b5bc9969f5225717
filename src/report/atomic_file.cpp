#include "report/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/random.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "report/temp_cleanup.hpp"

namespace ncvm {

namespace {
// True for an existing path that is not a regular file: /dev/null, a FIFO, /dev/stdout.
bool isSpecialFile(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 && !S_ISREG(st.st_mode);
}

std::string randomHex() {
  unsigned char bytes[8];
  if (::getrandom(bytes, sizeof bytes, 0) != static_cast<ssize_t>(sizeof bytes))
    throw std::runtime_error(
        fmt::format("no random bytes for a temporary name: {}", std::strerror(errno)));
  std::string s;
  for (unsigned char b : bytes) s += fmt::format("{:02x}", b);
  return s;
}

[[noreturn]] void cannot(const char* what, const std::string& path, int err) {
  throw std::runtime_error(fmt::format("{}: cannot {}: {}", path, what, std::strerror(err)));
}
}  // namespace

void writeFileAtomic(const std::string& path, std::string_view data) {
  AtomicFile f(path);
  if (!data.empty() && std::fwrite(data.data(), 1, data.size(), f.get()) != data.size())
    cannot("write", path, errno);
  f.commit();
}

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)),
      direct_(isStdoutPath(path_) || isSpecialFile(path_)),
      stdout_(isStdoutPath(path_)) {
  if (stdout_) {
    file_ = stdout;
    return;
  }
  if (direct_) {
    file_ = std::fopen(path_.c_str(), "wb");
    if (!file_) cannot("create", path_, errno);
  } else {
    removeStaleTemps(path_);
    int fd = -1;
    for (int attempt = 0; fd < 0 && attempt < 16; ++attempt) {
      temp_ = tempNameFor(path_, randomHex());
      fd = ::open(temp_.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0666);
      if (fd < 0 && errno != EEXIST) cannot("create", path_, errno);
    }
    if (fd < 0) cannot("create", path_, EEXIST);
    slot_ = registerTemp(temp_);
    file_ = ::fdopen(fd, "wb");
    if (!file_) {
      int err = errno;
      ::close(fd);
      discard();
      cannot("create", path_, err);
    }
  }
  constexpr size_t kBuffer = 1 << 16;
  buffer_ = std::make_unique<char[]>(kBuffer);
  std::setvbuf(file_, buffer_.get(), _IOFBF, kBuffer);
}

void AtomicFile::discard() {
  if (temp_.empty()) return;
  ::unlink(temp_.c_str());
  unregisterTemp(slot_);
  slot_ = -1;
}

AtomicFile::~AtomicFile() {
  if (!file_) return;
  if (stdout_) {
    std::fflush(stdout);
    return;
  }
  std::fclose(file_);
  discard();
}

void AtomicFile::commit() {
  std::FILE* f = file_;
  file_ = nullptr;
  if (stdout_) {
    if (std::fflush(f) != 0 || std::ferror(f)) cannot("write", "standard output", errno);
    return;
  }
  // An earlier write failed when the stream's error flag is set; its errno may be gone.
  bool ok = std::fflush(f) == 0 && !std::ferror(f);
  int err = ok ? 0 : (errno ? errno : EIO);
  if (ok && !direct_ && ::fsync(::fileno(f)) != 0) ok = false, err = errno;
  if (std::fclose(f) != 0 && ok) ok = false, err = errno;
  if (ok && !direct_ && std::rename(temp_.c_str(), path_.c_str()) != 0) ok = false, err = errno;
  if (!ok) {
    discard();
    cannot("write", path_, err);
  }
  unregisterTemp(slot_);
  slot_ = -1;
}

}  // namespace ncvm
