#pragma once

// The paper's study configuration (scenarios/titan/paper.yaml), shared by the TITAN study tests.

#include <string>

#include "motoflex/studies/titan/titan_study_config.hpp"

namespace motoflex::testing {

inline const TitanStudyConfig& titan_paper_config() {
  static const TitanStudyConfig config =
      load_titan_study_config(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/titan/paper.yaml");
  return config;
}

}  // namespace motoflex::testing
