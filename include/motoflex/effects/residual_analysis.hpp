#pragma once

// What the residual (measured − simulated encoder angle) of a parameter set looks like: per
// joint RMS and bias; binned against time, commanded velocity and load torque; split by the
// sign of the joint velocity and by contact phase; and its correlation with the commanded
// velocity at lags, with the lag that best aligns measured and simulated angles (a delay).

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "motoflex/fit/fitness.hpp"

namespace motoflex {

struct ResidualBins {
  std::string against;  // "time_s", "command_velocity_rad_s", "load_torque_nm"
  std::vector<double> center;
  std::vector<double> mean_deg;
  std::vector<double> rms_deg;
  std::vector<std::size_t> count;
};

struct JointResiduals {
  std::string joint;
  double rms_deg = 0.0;
  double mean_deg = 0.0;
  std::vector<ResidualBins> bins;
  double mean_moving_positive_deg = 0.0;  // joint velocity > 0 (simulated)
  double mean_moving_negative_deg = 0.0;
  double rms_double_support_deg = 0.0;  // NaN without feet / frames in that phase
  double rms_single_support_deg = 0.0;
  double rms_no_contact_deg = 0.0;
  std::vector<double> lag_s;            // −max..+max
  std::vector<double> lag_correlation;  // corr(residual(t), commanded velocity(t − lag))
  double best_lag_s = 0.0;  // argmin over lag of Σ (measured(t) − simulated(t − lag))²
};

struct ResidualAnalysis {
  double rms_deg = 0.0;
  std::vector<double> imu_rms_deg;  // torso roll, pitch; empty unless every log has IMU columns
  std::vector<JointResiduals> joints;
  // Time series for plots: one row per scored frame of every log.
  std::vector<std::string> series_columns;
  std::vector<std::vector<double>> series_rows;
};

ResidualAnalysis analyse_residuals(const FitnessFunction& fitness, const ParameterSet& set);

nlohmann::ordered_json residual_analysis_json(const ResidualAnalysis& analysis);
// CSV of the time series (case index, time, feet in contact, then per joint residual, commanded
// and simulated velocity, load torque; then the IMU's roll and pitch residuals if it has them).
std::string residual_series_csv(const ResidualAnalysis& analysis);

}  // namespace motoflex
