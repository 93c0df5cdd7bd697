#include "motoflex/fit/fit_report.hpp"

#include <cmath>
#include <filesystem>
#include <numbers>

#include "motoflex/sim/rollout_log.hpp"

namespace motoflex {
namespace {

constexpr double kDegPerRad = 180.0 / std::numbers::pi;

}  // namespace

DetailedEvaluation evaluate_in_detail(const FitnessFunction& fitness, const ParameterSet& set) {
  DetailedEvaluation out;
  out.breakdown = fitness.evaluate(set, std::numeric_limits<double>::infinity(), &out.rollouts);
  const std::size_t n = fitness.model().actuators.size();
  std::vector<double> sum_per_joint(n, 0.0);
  double imu_sum[2] = {0.0, 0.0};
  bool imu = true;
  std::size_t count = 0;
  for (std::size_t c = 0; c < fitness.cases().size(); ++c) {
    const FitCase& fit_case = fitness.cases()[c];
    const RolloutResult& r = out.rollouts[c];
    double case_sum = 0.0;
    std::size_t case_count = 0;
    imu = imu && !fit_case.measured_imu_rad.empty();
    for (std::size_t f = first_scored_frame(fit_case, fitness.options().settle_s);
         f < r.frames_completed; ++f) {
      for (std::size_t j = 0; j < n; ++j) {
        const double e = fit_case.measured_rad[f * n + j] - r.measured_rad[f * n + j];
        sum_per_joint[j] += e * e;
        case_sum += e * e;
      }
      if (imu) {
        const double roll = fit_case.measured_imu_rad[2 * f] - r.imu_roll_rad[f];
        const double pitch = fit_case.measured_imu_rad[2 * f + 1] - r.imu_pitch_rad[f];
        imu_sum[0] += roll * roll;
        imu_sum[1] += pitch * pitch;
      }
      ++count;
      ++case_count;
    }
    out.rms_deg_per_case.push_back(
        case_count == 0 ? 0.0 : std::sqrt(case_sum / (case_count * n)) * kDegPerRad);
  }
  double total = 0.0;
  for (std::size_t j = 0; j < n; ++j) {
    total += sum_per_joint[j];
    out.rms_deg_per_joint.push_back(count == 0 ? 0.0
                                               : std::sqrt(sum_per_joint[j] / count) * kDegPerRad);
  }
  out.rms_deg = count == 0 ? 0.0 : std::sqrt(total / (count * n)) * kDegPerRad;
  if (imu && count > 0) {
    for (const double sum : imu_sum) out.imu_rms_deg.push_back(std::sqrt(sum / count) * kDegPerRad);
  }
  return out;
}

nlohmann::ordered_json rms_json(const FitnessFunction& fitness, const DetailedEvaluation& eval) {
  nlohmann::ordered_json out;
  out["overall"] = eval.rms_deg;
  nlohmann::ordered_json per_joint = nlohmann::ordered_json::object();
  for (std::size_t j = 0; j < fitness.model().actuators.size(); ++j) {
    per_joint[fitness.model().actuators[j].name] = eval.rms_deg_per_joint[j];
  }
  out["per_joint"] = per_joint;
  if (!eval.imu_rms_deg.empty()) {
    out["imu"] = {{"roll", eval.imu_rms_deg[0]}, {"pitch", eval.imu_rms_deg[1]}};
  }
  return out;
}

nlohmann::ordered_json cases_json(const FitnessFunction& fitness, const DetailedEvaluation& eval) {
  nlohmann::ordered_json out = nlohmann::ordered_json::array();
  for (std::size_t c = 0; c < fitness.cases().size(); ++c) {
    const CaseScore& s = eval.breakdown.cases[c];
    nlohmann::ordered_json item;
    item["name"] = fitness.cases()[c].name;
    item["fitness"] = s.fitness;
    item["frames"] = s.frames;
    item["frames_requested"] = s.frames_requested;
    item["end"] = to_string(s.end);
    item["end_detail"] = s.end_detail;
    item["rms_deg"] = eval.rms_deg_per_case[c];
    out.push_back(item);
  }
  return out;
}

void write_simulated_logs(const std::string& folder, const FitnessFunction& fitness,
                          const DetailedEvaluation& eval, const std::string& origin) {
  std::filesystem::create_directories(folder);
  for (std::size_t c = 0; c < fitness.cases().size(); ++c) {
    const FitCase& fit_case = fitness.cases()[c];
    if (eval.rollouts[c].frames_completed < 2) continue;
    JointLogMeta meta;
    meta.robot = fitness.model().name;
    meta.rate_hz = (fit_case.commands.frames() - 1) / fit_case.commands.duration_s();
    meta.motion = fit_case.name;
    meta.origin = origin;
    if (eval.rollouts[c].end != RolloutEnd::kCompleted) {
      meta.notes =
          std::string(to_string(eval.rollouts[c].end)) + ": " + eval.rollouts[c].end_detail;
    }
    write_joint_log((std::filesystem::path(folder) / (fit_case.name + ".csv")).string(),
                    joint_log_from_rollout(eval.rollouts[c], meta));
  }
}

}  // namespace motoflex
