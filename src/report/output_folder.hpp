#pragma once
// An output written as a set of files (--stock-out DIR): the files go into a temporary folder
// beside DIR, and commit() puts the whole folder in place at once (a rename, or an atomic
// exchange with the previous DIR, which is then removed). A kill or a full disk leaves
// either the previous set or the new one, never files of two runs side by side; an
// uncommitted temporary folder is removed by the destructor, on SIGINT/SIGTERM/SIGHUP, or by
// the next run when its process was killed (temp_cleanup.hpp).
#include <string>

namespace ncvm {

class OutputFolder {
 public:
  // Throws std::runtime_error when `path` exists and is not a folder ncvm may replace: a
  // file, or a folder holding a subfolder or no analysis.json (not a previous stock output;
  // replacing it would lose the user's files).
  explicit OutputFolder(std::string path);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;
  // Where the files are written until commit().
  const std::string& temporary() const { return temp_; }
  void commit();

 private:
  std::string path_, temp_;
  int slot_ = -1;  // temp_cleanup's registration of temp_
  bool committed_ = false;
};

}  // namespace ncvm
