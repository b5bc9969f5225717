#pragma once
// Which files are programs and which setup a program runs with: one rule for the --lib
// folders, the bundled macros, `ncvm serve`'s listing, `ncvm list` and `make demo`
// (docs/setup-format.md, "Which setup goes with which program").
#include <filesystem>
#include <string>
#include <vector>

namespace ncvm {

// A program file: one of the extensions Fanuc shops and DNC software use (.nc .tap .txt .min
// .cnc .ptp .eia .iso .anc, in any case), or no extension and a program name: O (or o)
// followed by digits, as a control's memory card or a DNC folder holds them (O9100, o9100).
// CMakeLists.txt is not one.
bool isProgramFileName(const std::filesystem::path& file);

// The names of the setup files a program may run with, best first, as names in the
// program's own folder: its own name with .toml (ellipse.nc -> ellipse.toml); then, for a
// variant named NAME-VARIANT, NAME.toml, dropping one "-part" at a time
// (face-milling-g42-x150.nc -> face-milling-g42.toml); then setup.toml. The first that
// exists is the setup; none: the default machine.
std::vector<std::string> setupCandidates(const std::filesystem::path& program);

// The setup file beside `program` by that rule, or an empty path.
std::filesystem::path setupFileFor(const std::filesystem::path& program);

// Every program file under `dir` (`depth` folder levels below it at most), sorted.
std::vector<std::filesystem::path> programFilesUnder(const std::filesystem::path& dir, int depth);

}  // namespace ncvm
