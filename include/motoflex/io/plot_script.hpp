#pragma once

#include <string>

namespace motoflex::cli {

// Runs scripts/plot_log.py (python3 with matplotlib) to draw commanded vs measured angles of
// a joint log into `png_path`. Returns false (after printing why) when plotting is unavailable;
// the log itself is never affected.
bool plot_joint_log(const std::string& csv_path, const std::string& png_path);

}  // namespace motoflex::cli
