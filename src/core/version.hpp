#pragma once
// The version of ncvm, from one place: CMake's project(VERSION), and the git commit the
// build was configured at (src/CMakeLists.txt).

namespace ncvm {

// The project version, e.g. "1.2.0".
const char* versionNumber();
// The version with the commit, e.g. "1.2.0 (git 1a2b3c4)"; only the version outside git.
const char* versionText();

}  // namespace ncvm
