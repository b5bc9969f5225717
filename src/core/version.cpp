#include "core/version.hpp"

namespace ncvm {

const char* versionNumber() {
  return NCVM_VERSION;
}

const char* versionText() {
  return sizeof(NCVM_GIT_COMMIT) > 1 ? NCVM_VERSION " (git " NCVM_GIT_COMMIT ")" : NCVM_VERSION;
}

}  // namespace ncvm
