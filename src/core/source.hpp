#pragma once
// Where a piece of program text came from: every block, word and expression keeps one,
// so an alarm can point at FILE:LINE:COL like a compiler does.
#include <cstdint>
#include <string>
#include <vector>

namespace ncvm {

struct SourceLoc {
  uint32_t file = 0;  // index into SourceFiles
  uint32_t line = 0;  // 1-based; 0 = unknown
  uint32_t col = 0;   // 1-based
};

// The registry of loaded file names; SourceLoc::file indexes it.
class SourceFiles {
 public:
  uint32_t add(std::string path) {
    names_.push_back(std::move(path));
    return static_cast<uint32_t>(names_.size() - 1);
  }
  const std::string& name(uint32_t id) const {
    static const std::string unknown = "<unknown>";
    return id < names_.size() ? names_[id] : unknown;
  }

 private:
  std::vector<std::string> names_;
};

}  // namespace ncvm
