#pragma once
// Output files are written whole or not at all: write a temporary file beside the target,
// flush it to disk, then rename it over the target. A kill at any point leaves either the
// old file or the new one.
#include <cstdio>
#include <string>
#include <string_view>

namespace ncvm {

// Throws std::runtime_error on failure.
void writeFileAtomic(const std::string& path, std::string_view data);

// For large outputs written as they are produced (the trace): open a temporary file,
// stream into it, then commit() renames it into place. The destructor removes an
// uncommitted temporary.
class AtomicFile {
 public:
  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  std::FILE* get() const { return file_; }
  void commit();

 private:
  std::string path_, temp_;
  std::FILE* file_ = nullptr;
};

}  // namespace ncvm
