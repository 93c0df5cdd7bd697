#pragma once

#include <string>
#include <vector>

namespace motoflex {

// Runs scripts/<script> (python3 with matplotlib, from Debian's /usr/bin/python3 when present)
// with the given arguments. Plots are a convenience: returns false after printing a one-line
// warning when python or the script is unavailable or fails; never throws.
bool run_plot_script(const std::string& script, const std::vector<std::string>& arguments);

// scripts/plot_log.py: commanded vs measured angle per joint (and IMU) of a joint log, with an
// optional second log whose .meas columns are overlaid.
bool plot_joint_log(const std::string& csv_path, const std::string& png_path,
                    const std::string& compare_csv = "");

}  // namespace motoflex
