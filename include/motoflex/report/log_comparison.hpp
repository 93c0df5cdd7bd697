#pragma once

// One log of a fit, measured against simulated, as the report plots it: per joint (and torso
// IMU angle, when both logs have one) the measured and the simulated angle in degrees on the
// measured log's time grid, thinned for the browser.

#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <optional>

#include "motoflex/io/joint_log.hpp"
#include "motoflex/report/frequency_response.hpp"

namespace motoflex::report {

struct ChannelComparison {
  std::string name;  // joint name, or "imu.roll" / "imu.pitch"
  // RMS and largest magnitude of measured − simulated over the frames both logs cover (deg);
  // NaN when they share no frame.
  double rms_deg = 0.0;
  double max_abs_deg = 0.0;
  // Indices into the log's time grid of the points drawn; empty: every frame.
  std::vector<std::size_t> frames;
  std::vector<double> measured_deg;   // at the drawn frames
  std::vector<double> simulated_deg;  // NaN where the simulation did not reach the frame
  // A joint's response to its command, measured and simulated (frequency_response.hpp), over
  // every frame both cover; none for the IMU angles, a log without commands, or a command that
  // does not move.
  std::optional<FrequencyComparison> frequency;
};

struct LogComparison {
  std::string name;            // the log's stem ("walk_050mm_2s")
  std::string set;             // "training" or "validation"
  std::vector<double> time_s;  // the measured log's frames
  std::size_t frames_simulated = 0;
  double simulated_end_s = 0.0;  // last simulated frame (a fall or a fit window ends earlier)
  bool thinned = false;          // some channel draws fewer points than there are frames
  std::vector<ChannelComparison> channels;
};

// Compares the measured log (its .meas columns) with the simulated one (`simulated`'s .meas
// columns: the fit's simulated encoders) channel by channel, for every joint of `simulated`
// that `measured` measures, plus imu.roll and imu.pitch when both logs have them. The
// simulated angles are interpolated linearly onto the measured frames (the fit writes them on
// the same grid; interpolation only matters for logs written otherwise). A channel with more
// than `max_points` frames keeps, for at most max_points frames, the envelope (see
// envelope_indices) of its measured, simulated and residual angle, a third of the budget each,
// so that every trace keeps its peaks. Each joint with a commanded angle in `measured` also gets
// its frequency response (before any thinning).
LogComparison compare_logs(const JointLog& measured, const JointLog& simulated,
                           std::size_t max_points);

// {"name", "set", "t": [s...], "frames_simulated", "simulated_end_s", "thinned",
//  "channels": [{"name", "rms_deg", "max_abs_deg", "t": [...] (only when thinned), "measured":
//  [...], "simulated": [...], "frequency": {...} (when there is one,
//  frequency_comparison_json)}]}; degrees rounded to 6 significant digits, times to 1 µs, NaN
// as null. The page's script computes the residual measured − simulated from these.
nlohmann::json log_comparison_json(const LogComparison& comparison);

}  // namespace motoflex::report
