#pragma once
// The bundled data (macros/, presets/) as the library finds them: beside the shared object
// that holds this code (libncvm.so in PREFIX/lib, or the Python module in
// PREFIX/lib/python3/dist-packages/ncvm), not beside the program that embeds it.
#include <string>

namespace ncvm::api {

// $NCVM_DATA when set; else the nearest PREFIX/share/ncvm above this shared object (or
// executable); else the source tree the library was built from. Empty when none exists.
std::string findDataFolder();

// PATH/NAME.toml in the data folder's presets/, or empty when there is no such preset.
std::string presetPath(const std::string& name);

}  // namespace ncvm::api
