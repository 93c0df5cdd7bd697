#pragma once
// Where the real servo logs of ../shared/data/bam are (BAM's recordings; not part of the
// repository, so a user's machine has none): the tests that replay them skip without them.

#include <cstdio>
#include <filesystem>
#include <string>

namespace motoflex::testing {

// ../shared/data/bam/<subfolder> beside the source tree, or an empty path after printing why a
// test that needs it is skipped (the caller then GTEST_SKIPs).
inline std::filesystem::path bam_data_or_empty(const std::string& subfolder) {
  const std::filesystem::path folder =
      std::filesystem::path(MOTOFLEX_SOURCE_DIR) / ".." / "shared" / "data" / "bam" / subfolder;
  if (std::filesystem::is_directory(folder)) return folder;
  std::printf("skipped: %s is absent (real BAM logs are not part of the repository)\n",
              folder.string().c_str());
  return {};
}

}  // namespace motoflex::testing
