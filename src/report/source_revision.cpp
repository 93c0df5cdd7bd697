#include "motoflex/report/report_page.hpp"

// MOTOFLEX_GIT_REVISION is set for this file only (src/report/CMakeLists.txt, from `git describe`
// at configure time, which scripts/build runs on every build), so a new commit rebuilds only
// this file.

namespace motoflex::report {

const char* source_revision() {
  return MOTOFLEX_GIT_REVISION;
}

}  // namespace motoflex::report
