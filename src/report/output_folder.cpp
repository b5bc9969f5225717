#include "report/output_folder.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <linux/fs.h>
#include <stdio.h>
#include <sys/random.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "report/temp_cleanup.hpp"

namespace ncvm {

namespace fs = std::filesystem;

namespace {
// A folder ncvm may replace as a whole: empty, or a previous stock output (analysis.json and
// plain files only).
void checkReplaceable(const std::string& path) {
  std::error_code ec;
  const auto st = fs::symlink_status(path, ec);
  if (ec || st.type() == fs::file_type::not_found) return;
  if (st.type() != fs::file_type::directory)
    throw std::runtime_error(fmt::format("{}: not a folder (--stock-out names a folder)", path));
  bool empty = true, stock = false;
  for (const auto& e : fs::directory_iterator(path, ec)) {
    empty = false;
    if (e.is_directory() || e.is_symlink())
      throw std::runtime_error(fmt::format(
          "{}: holds {}, so it is not a stock output ncvm may replace; give a new or empty folder",
          path, e.path().filename().string()));
    stock = stock || e.path().filename() == "analysis.json";
  }
  if (ec) throw std::runtime_error(fmt::format("{}: cannot read: {}", path, ec.message()));
  if (!empty && !stock)
    throw std::runtime_error(
        fmt::format("{}: holds files but no analysis.json, so it is not a stock output ncvm may "
                    "replace; give a new or "
                    "empty folder",
                    path));
}
}  // namespace

OutputFolder::OutputFolder(std::string path) : path_(std::move(path)) {
  while (!path_.empty() && path_.size() > 1 && path_.back() == '/') path_.pop_back();
  checkReplaceable(path_);
  removeStaleTemps(path_);
  for (int attempt = 0; attempt < 16 && temp_.empty(); ++attempt) {
    unsigned char bytes[8];
    if (::getrandom(bytes, sizeof bytes, 0) != static_cast<ssize_t>(sizeof bytes))
      throw std::runtime_error(fmt::format("{}: no random bytes for a temporary name", path_));
    std::string hex;
    for (unsigned char b : bytes) hex += fmt::format("{:02x}", b);
    std::string candidate = tempNameFor(path_, hex);
    if (::mkdir(candidate.c_str(), 0777) == 0)
      temp_ = candidate;
    else if (errno != EEXIST)
      throw std::runtime_error(fmt::format("{}: cannot create: {}", path_, std::strerror(errno)));
  }
  if (temp_.empty())
    throw std::runtime_error(fmt::format("{}: cannot create a temporary folder", path_));
  slot_ = registerTemp(temp_, true);
}

OutputFolder::~OutputFolder() {
  std::error_code ec;
  if (!committed_) fs::remove_all(temp_, ec);
  unregisterTemp(slot_);
}

void OutputFolder::commit() {
  checkReplaceable(path_);  // as it is now, not as it was before the run
  std::error_code ec;
  if (!fs::exists(fs::symlink_status(path_, ec))) {
    if (std::rename(temp_.c_str(), path_.c_str()) != 0)
      throw std::runtime_error(fmt::format("{}: cannot write: {}", path_, std::strerror(errno)));
  } else {
    // One step: the new set takes the old one's place, the old one the temporary's name.
    if (::renameat2(AT_FDCWD, temp_.c_str(), AT_FDCWD, path_.c_str(), RENAME_EXCHANGE) != 0)
      throw std::runtime_error(fmt::format("{}: cannot replace: {}", path_, std::strerror(errno)));
    // The temporary name now holds the previous set: the handler may still remove it.
    fs::remove_all(temp_, ec);
  }
  unregisterTemp(slot_);
  slot_ = -1;
  committed_ = true;
}

}  // namespace ncvm
