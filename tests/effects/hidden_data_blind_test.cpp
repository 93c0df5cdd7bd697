// The logs with an undeclared effect (reference_data/hidden/<effect>/{train,validation}) must not
// give the effect away: no sidecar field names an effect of the library or the truth file it was
// recorded from (`motoflex record --blind`). Only the folder the user picks and the withheld
// truth (reference_data/hidden/truth/) say what is in them.

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "motoflex/model/effect_library.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

TEST(HiddenData, SidecarsDoNotNameTheirEffect) {
  const fs::path root = fs::path(MOTOFLEX_SOURCE_DIR) / "reference_data" / "hidden";
  ASSERT_TRUE(fs::exists(root));
  std::size_t sidecars = 0;
  for (const auto& set : fs::directory_iterator(root)) {
    const std::string effect = set.path().filename().string();
    if (effect == "truth" || !set.is_directory()) continue;
    for (const auto& entry : fs::recursive_directory_iterator(set.path())) {
      if (entry.path().extension() != ".yaml") continue;
      std::ifstream in(entry.path());
      std::stringstream text;
      text << in.rdbuf();
      const std::string content = lower(text.str());
      ++sidecars;
      EXPECT_EQ(content.find(lower(effect)), std::string::npos) << entry.path();
      for (const Effect& e : effect_library()) {
        EXPECT_EQ(content.find(lower(e.name)), std::string::npos)
            << entry.path() << " names the effect " << e.name;
      }
    }
  }
  EXPECT_GE(sidecars, 21u);  // 7 sets (6 effects and none) x train + validation logs
}

}  // namespace
}  // namespace motoflex
