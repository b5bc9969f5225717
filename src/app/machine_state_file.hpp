#pragma once
// The --machine-state file for one run. Runs that share one machine state take turns: the
// file is locked (flock on PATH.lock beside it) from before it is read until after the new
// state is written, so no run reads a state another run is about to replace and no update
// is lost. The lock belongs to the open file, so a killed run never leaves it held; the
// lock file itself stays (removing it would let two runs lock two different files).
#include <nlohmann/json.hpp>
#include <string>

#include "machine/setup.hpp"

namespace ncvm {

class MachineStateFile {
 public:
  // Locks the file, waiting at most waitSeconds while another run holds it; throws
  // std::runtime_error naming the file and the wait.
  MachineStateFile(std::string path, double waitSeconds);
  ~MachineStateFile();
  MachineStateFile(const MachineStateFile&) = delete;
  MachineStateFile& operator=(const MachineStateFile&) = delete;

  // The file's memory, every value checked against the setup's machine (memoryFromJson),
  // or nullptr when the file does not exist yet. Throws naming the file, the key and the
  // value; the file is left as it is.
  const nlohmann::json* load(const Setup& setup);
  // Writes the new memory atomically, still under the lock.
  void save(const std::string& text);
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  int lockFd_ = -1;
  nlohmann::json memory_;
};

}  // namespace ncvm
