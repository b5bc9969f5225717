#pragma once
// Output files are written whole or not at all: write a temporary file beside the target,
// flush it to disk, then rename it over the target. A kill at any point leaves either the
// old file or the new one. The temporary is created exclusively (O_EXCL|O_NOFOLLOW) under an
// unpredictable name, so a file or symlink planted in its place is never written through;
// it is removed on an error, on SIGINT/SIGTERM/SIGHUP, and by the next run when its process
// was killed (temp_cleanup.hpp).
#include <cstdio>
#include <memory>
#include <string>
#include <string_view>

namespace ncvm {

// Throws std::runtime_error on failure.
void writeFileAtomic(const std::string& path, std::string_view data);

// True for the path `-`, which names standard output.
inline bool isStdoutPath(std::string_view path) {
  return path == "-";
}

// For large outputs written as they are produced (the trace): open a temporary file,
// stream into it, then commit() renames it into place. The destructor removes an
// uncommitted temporary. A path that exists and is not a regular file (/dev/null, a pipe,
// a FIFO, /dev/stdout) is written directly: renaming over a device would replace it; `-` is
// standard output.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::FILE* get() const { return file_; }
  void commit();

 private:
  void discard();
  std::string path_, temp_;
  std::FILE* file_ = nullptr;
  bool direct_ = false;             // writing straight into a device or pipe
  bool stdout_ = false;             // the path `-`
  int slot_ = -1;                   // temp_cleanup's registration of temp_
  std::unique_ptr<char[]> buffer_;  // per file: batch runs write traces from several threads
};

}  // namespace ncvm
