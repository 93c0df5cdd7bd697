#include "motoflex/effects/residual_analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>

namespace motoflex {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;
constexpr std::size_t kBins = 12;
constexpr int kMaxLagFrames = 10;
constexpr double kContactForce_n = 1.0;  // a foot carrying more is in contact

// Per scored frame of every case: what the analysis needs, joint-major within a frame.
struct Sample {
  std::size_t case_index = 0;
  double time_s = 0.0;
  int feet_in_contact = -1;  // −1: the robot has no feet
  std::vector<double> residual_rad, command_velocity, joint_velocity, torque_nm;
  double imu_residual_rad[2] = {0.0, 0.0};  // roll, pitch (when every log has IMU columns)
};

double central_difference(const std::vector<double>& values, const std::vector<double>& time,
                          std::size_t frames, std::size_t joints, std::size_t f, std::size_t j) {
  const std::size_t lo = f == 0 ? 0 : f - 1;
  const std::size_t hi = std::min(f + 1, frames - 1);
  if (hi == lo) return 0.0;
  return (values[hi * joints + j] - values[lo * joints + j]) / (time[hi] - time[lo]);
}

ResidualBins bin(const std::string& against, const std::vector<double>& x,
                 const std::vector<double>& r) {
  ResidualBins out;
  out.against = against;
  if (x.empty()) return out;
  const auto [lo_it, hi_it] = std::minmax_element(x.begin(), x.end());
  const double lo = *lo_it, hi = *hi_it;
  const double width = hi > lo ? (hi - lo) / kBins : 1.0;
  std::vector<double> sum(kBins, 0.0), sum2(kBins, 0.0);
  std::vector<std::size_t> count(kBins, 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t b =
        std::min<std::size_t>(kBins - 1, static_cast<std::size_t>((x[i] - lo) / width));
    sum[b] += r[i];
    sum2[b] += r[i] * r[i];
    ++count[b];
  }
  for (std::size_t b = 0; b < kBins; ++b) {
    if (count[b] == 0) continue;
    out.center.push_back(lo + (b + 0.5) * width);
    out.mean_deg.push_back(sum[b] / count[b] * kDegPerRad);
    out.rms_deg.push_back(std::sqrt(sum2[b] / count[b]) * kDegPerRad);
    out.count.push_back(count[b]);
  }
  return out;
}

double rms_deg_of(const std::vector<double>& r) {
  if (r.empty()) return std::numeric_limits<double>::quiet_NaN();
  double s = 0.0;
  for (double v : r) s += v * v;
  return std::sqrt(s / r.size()) * kDegPerRad;
}

double mean_deg_of(const std::vector<double>& r) {
  if (r.empty()) return std::numeric_limits<double>::quiet_NaN();
  double s = 0.0;
  for (double v : r) s += v;
  return s / r.size() * kDegPerRad;
}

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const std::size_t n = a.size();
  if (n < 2) return 0.0;
  double ma = 0.0, mb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    ma += a[i];
    mb += b[i];
  }
  ma /= n;
  mb /= n;
  double sab = 0.0, saa = 0.0, sbb = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0.0 && sbb > 0.0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

}  // namespace

namespace {

// The scored frames of every case as samples, with the inputs of the lag search per joint:
// Σ (measured(t) − simulated(t − lag))² and the residual/velocity pairs for the correlation.
struct CollectedResiduals {
  std::vector<Sample> samples;
  std::vector<std::vector<double>> lag_sse;                    // [joint][lag]
  std::vector<std::vector<std::vector<double>>> lag_r, lag_v;  // [joint][lag][sample]
  double period_s = 0.01;
  bool imu = true;
  std::vector<double> imu_residual[2];
};

void collect_frame_lags(const FitCase& fit_case, const RolloutResult& r, std::size_t first,
                        std::size_t f, std::size_t j, std::size_t n, double residual,
                        CollectedResiduals& out) {
  const std::size_t frames = r.frames_completed;
  const std::size_t k = f * n + j;
  for (int lag = -kMaxLagFrames; lag <= kMaxLagFrames; ++lag) {
    const long g = static_cast<long>(f) - lag;
    if (g < static_cast<long>(first) || g >= static_cast<long>(frames)) continue;
    const std::size_t li = static_cast<std::size_t>(lag + kMaxLagFrames);
    const double e = fit_case.measured_rad[k] - r.measured_rad[g * n + j];
    out.lag_sse[j][li] += e * e;
    out.lag_r[j][li].push_back(residual);
    out.lag_v[j][li].push_back(
        central_difference(r.commanded_rad, r.time_s, frames, n, static_cast<std::size_t>(g), j));
  }
}

Sample frame_sample(const FitCase& fit_case, const RolloutResult& r, std::size_t c, std::size_t f,
                    std::size_t n, bool imu) {
  const std::size_t frames = r.frames_completed;
  const std::vector<double>& time = r.time_s;
  Sample s;
  s.case_index = c;
  s.time_s = time[f] - time[0];
  const std::size_t feet = r.foot_force_z_n.size() / frames;  // per frame
  if (feet > 0) {
    s.feet_in_contact = 0;
    for (std::size_t k = 0; k < feet; ++k) {
      if (r.foot_force_z_n[f * feet + k] > kContactForce_n) ++s.feet_in_contact;
    }
  }
  if (imu) {
    s.imu_residual_rad[0] = fit_case.measured_imu_rad[2 * f] - r.imu_roll_rad[f];
    s.imu_residual_rad[1] = fit_case.measured_imu_rad[2 * f + 1] - r.imu_pitch_rad[f];
  }
  for (std::size_t j = 0; j < n; ++j) {
    const std::size_t k = f * n + j;
    s.residual_rad.push_back(fit_case.measured_rad[k] - r.measured_rad[k]);
    s.command_velocity.push_back(central_difference(r.commanded_rad, time, frames, n, f, j));
    s.joint_velocity.push_back(central_difference(r.measured_rad, time, frames, n, f, j));
    s.torque_nm.push_back(r.joint_torque_nm.empty() ? 0.0 : r.joint_torque_nm[k]);
  }
  return s;
}

CollectedResiduals collect_residuals(const std::vector<FitCase>& cases,
                                     const std::vector<RolloutResult>& rollouts, double settle_s,
                                     std::size_t n) {
  CollectedResiduals out;
  const std::size_t lags = 2 * kMaxLagFrames + 1;
  out.lag_sse.assign(n, std::vector<double>(lags, 0.0));
  out.lag_r.assign(n, std::vector<std::vector<double>>(lags));
  out.lag_v.assign(n, std::vector<std::vector<double>>(lags));
  for (const FitCase& c : cases) out.imu = out.imu && !c.measured_imu_rad.empty();
  double total_s = 0.0;
  std::size_t periods = 0;
  for (std::size_t c = 0; c < cases.size(); ++c) {
    const RolloutResult& r = rollouts[c];
    const std::size_t frames = r.frames_completed;
    if (frames < 2) continue;
    total_s += r.time_s[frames - 1] - r.time_s[0];
    periods += frames - 1;
    const std::size_t first = first_scored_frame(cases[c], settle_s);
    for (std::size_t f = first; f < frames; ++f) {
      Sample s = frame_sample(cases[c], r, c, f, n, out.imu);
      if (out.imu) {
        for (int a = 0; a < 2; ++a) out.imu_residual[a].push_back(s.imu_residual_rad[a]);
      }
      for (std::size_t j = 0; j < n; ++j) {
        collect_frame_lags(cases[c], r, first, f, j, n, s.residual_rad[j], out);
      }
      out.samples.push_back(std::move(s));
    }
  }
  if (periods > 0) out.period_s = total_s / periods;
  return out;
}

JointResiduals summarise_joint(const CollectedResiduals& in, std::size_t j, const std::string& name,
                               std::vector<double>& all) {
  JointResiduals jr;
  jr.joint = name;
  std::vector<double> r, t, v, tau, positive, negative, double_support, single, none;
  for (const Sample& s : in.samples) {
    r.push_back(s.residual_rad[j]);
    t.push_back(s.time_s);
    v.push_back(s.command_velocity[j]);
    tau.push_back(s.torque_nm[j]);
    (s.joint_velocity[j] >= 0.0 ? positive : negative).push_back(s.residual_rad[j]);
    if (s.feet_in_contact >= 2) double_support.push_back(s.residual_rad[j]);
    if (s.feet_in_contact == 1) single.push_back(s.residual_rad[j]);
    if (s.feet_in_contact == 0) none.push_back(s.residual_rad[j]);
  }
  all.insert(all.end(), r.begin(), r.end());
  jr.rms_deg = rms_deg_of(r);
  jr.mean_deg = mean_deg_of(r);
  jr.bins.push_back(bin("time_s", t, r));
  jr.bins.push_back(bin("command_velocity_rad_s", v, r));
  jr.bins.push_back(bin("load_torque_nm", tau, r));
  jr.mean_moving_positive_deg = mean_deg_of(positive);
  jr.mean_moving_negative_deg = mean_deg_of(negative);
  jr.rms_double_support_deg = rms_deg_of(double_support);
  jr.rms_single_support_deg = rms_deg_of(single);
  jr.rms_no_contact_deg = rms_deg_of(none);
  std::size_t best = kMaxLagFrames;
  // Compare mean squared errors (the overlap shrinks with the lag).
  const auto mse = [&](std::size_t i) {
    return in.lag_r[j][i].empty() ? std::numeric_limits<double>::infinity()
                                  : in.lag_sse[j][i] / in.lag_r[j][i].size();
  };
  for (int lag = -kMaxLagFrames; lag <= kMaxLagFrames; ++lag) {
    const std::size_t li = static_cast<std::size_t>(lag + kMaxLagFrames);
    jr.lag_s.push_back(lag * in.period_s);
    jr.lag_correlation.push_back(correlation(in.lag_r[j][li], in.lag_v[j][li]));
    if (mse(li) < mse(best)) best = li;
  }
  jr.best_lag_s = (static_cast<double>(best) - kMaxLagFrames) * in.period_s;
  return jr;
}

void fill_series(const CollectedResiduals& in, const RobotModel& model, ResidualAnalysis& out) {
  const std::size_t n = model.actuators.size();
  out.series_columns = {"case", "time_s", "feet_in_contact"};
  for (const auto& a : model.actuators) {
    for (const char* leaf :
         {".residual_rad", ".command_velocity_rad_s", ".velocity_rad_s", ".load_torque_nm"}) {
      out.series_columns.push_back(a.name + leaf);
    }
  }
  if (in.imu) {
    out.series_columns.insert(out.series_columns.end(),
                              {"imu.roll.residual_rad", "imu.pitch.residual_rad"});
  }
  for (const Sample& s : in.samples) {
    std::vector<double> row = {static_cast<double>(s.case_index), s.time_s,
                               static_cast<double>(s.feet_in_contact)};
    for (std::size_t j = 0; j < n; ++j) {
      row.insert(row.end(),
                 {s.residual_rad[j], s.command_velocity[j], s.joint_velocity[j], s.torque_nm[j]});
    }
    if (in.imu) row.insert(row.end(), {s.imu_residual_rad[0], s.imu_residual_rad[1]});
    out.series_rows.push_back(std::move(row));
  }
}

}  // namespace

ResidualAnalysis analyse_residuals(const FitnessFunction& fitness, const ParameterSet& set) {
  // Simulate with the actuator torques recorded.
  std::vector<FitCase> cases = fitness.cases();
  for (auto& c : cases) c.options.record_torques = true;
  const FitnessFunction with_torques(std::make_shared<const RobotModel>(fitness.model()), cases,
                                     fitness.options());
  std::vector<RolloutResult> rollouts;
  with_torques.evaluate(set, std::numeric_limits<double>::infinity(), &rollouts);
  const RobotModel& model = fitness.model();
  const CollectedResiduals collected =
      collect_residuals(cases, rollouts, fitness.options().settle_s, model.actuators.size());
  ResidualAnalysis out;
  std::vector<double> all;
  for (std::size_t j = 0; j < model.actuators.size(); ++j) {
    out.joints.push_back(summarise_joint(collected, j, model.actuators[j].name, all));
  }
  out.rms_deg = rms_deg_of(all);
  if (collected.imu) {
    for (const auto& r : collected.imu_residual) out.imu_rms_deg.push_back(rms_deg_of(r));
  }
  fill_series(collected, model, out);
  return out;
}

nlohmann::ordered_json residual_analysis_json(const ResidualAnalysis& analysis) {
  const auto number = [](double v) -> nlohmann::ordered_json {
    return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
  };
  nlohmann::ordered_json out;
  out["rms_deg"] = analysis.rms_deg;
  if (!analysis.imu_rms_deg.empty()) {
    out["imu_rms_deg"] = {{"roll", number(analysis.imu_rms_deg[0])},
                          {"pitch", number(analysis.imu_rms_deg[1])}};
  }
  for (const JointResiduals& jr : analysis.joints) {
    nlohmann::ordered_json j;
    j["joint"] = jr.joint;
    j["rms_deg"] = number(jr.rms_deg);
    j["mean_deg"] = number(jr.mean_deg);
    j["mean_deg_by_velocity_sign"] = {{"positive", number(jr.mean_moving_positive_deg)},
                                      {"negative", number(jr.mean_moving_negative_deg)}};
    j["rms_deg_by_contact"] = {{"double_support", number(jr.rms_double_support_deg)},
                               {"single_support", number(jr.rms_single_support_deg)},
                               {"no_contact", number(jr.rms_no_contact_deg)}};
    j["best_lag_s"] = jr.best_lag_s;
    j["lag_s"] = jr.lag_s;
    j["lag_correlation_with_command_velocity"] = jr.lag_correlation;
    for (const ResidualBins& b : jr.bins) {
      j["binned"][b.against] = {{"center", b.center},
                                {"mean_deg", b.mean_deg},
                                {"rms_deg", b.rms_deg},
                                {"count", b.count}};
    }
    out["joints"].push_back(j);
  }
  return out;
}

std::string residual_series_csv(const ResidualAnalysis& analysis) {
  std::ostringstream csv;
  csv.precision(9);
  for (std::size_t i = 0; i < analysis.series_columns.size(); ++i) {
    csv << (i ? "," : "") << analysis.series_columns[i];
  }
  csv << "\n";
  for (const auto& row : analysis.series_rows) {
    for (std::size_t i = 0; i < row.size(); ++i) csv << (i ? "," : "") << row[i];
    csv << "\n";
  }
  return csv.str();
}

}  // namespace motoflex
