#include "motoflex/core/build_info.hpp"

#include <cstdlib>
#include <filesystem>

// MOTOFLEX_VERSION, MOTOFLEX_SOURCE_DIR and MOTOFLEX_INSTALL_DATA_DIR are set for this file
// only (src/core/CMakeLists.txt), so that nothing else is rebuilt when they change.

namespace motoflex {

const char* version() {
  return MOTOFLEX_VERSION;
}

std::string data_directory() {
  if (const char* dir = std::getenv("MOTOFLEX_DATA_DIR"); dir != nullptr && *dir != '\0') {
    return dir;
  }
  std::error_code error;
  if (std::filesystem::is_directory(std::filesystem::path(MOTOFLEX_SOURCE_DIR) / "scripts",
                                    error)) {
    return MOTOFLEX_SOURCE_DIR;
  }
  return MOTOFLEX_INSTALL_DATA_DIR;
}

}  // namespace motoflex
