#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "motoflex/fit/fitness.hpp"

namespace motoflex {

// A parameter set evaluated in full on a list of logs, with the residuals kept.
struct DetailedEvaluation {
  FitnessBreakdown breakdown;
  std::vector<RolloutResult> rollouts;
  // RMS of measured − simulated over the scored frames, in degrees.
  double rms_deg = 0.0;
  std::vector<double> rms_deg_per_joint;  // model actuator order
  std::vector<double> rms_deg_per_case;
  // RMS of the torso IMU's roll and pitch, measured − simulated (deg); empty unless every log
  // has IMU columns.
  std::vector<double> imu_rms_deg;
};

DetailedEvaluation evaluate_in_detail(const FitnessFunction& fitness, const ParameterSet& set);

// {"overall": x, "per_joint": {"LHipRoll": x, ...}} in degrees, and "imu": {"roll", "pitch"}
// when the logs have IMU columns.
nlohmann::ordered_json rms_json(const FitnessFunction& fitness, const DetailedEvaluation& eval);
// [{"name", "fitness", "frames", "frames_requested", "end", "end_detail", "rms_deg"}, ...]
nlohmann::ordered_json cases_json(const FitnessFunction& fitness, const DetailedEvaluation& eval);

// Writes one log per case into `folder`: the commanded angles as .cmd and the simulated
// encoders as .meas (compare with the measured log of the same name).
void write_simulated_logs(const std::string& folder, const FitnessFunction& fitness,
                          const DetailedEvaluation& eval, const std::string& origin);

}  // namespace motoflex
