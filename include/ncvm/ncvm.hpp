#pragma once
// ncvm's C++ API (docs/embedding.md): load programs and setups, run them with an event
// handler, read the end state, alarms and warnings. Link ncvm::ncvm (CMake:
// find_package(ncvm CONFIG REQUIRED)) or `pkg-config --cflags --libs ncvm`.
#include <string>

#include "ncvm/events.hpp"
#include "ncvm/export.hpp"
#include "ncvm/job.hpp"
#include "ncvm/result.hpp"

namespace ncvm::api {

// "0.1.0 (f252d7a)": the version of the library, as `ncvm --version` prints it.
NCVM_API std::string version();

}  // namespace ncvm::api
