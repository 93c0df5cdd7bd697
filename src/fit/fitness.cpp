#include "motoflex/fit/fitness.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

#include "motoflex/sim/ode_runtime.hpp"

namespace motoflex {

std::size_t first_scored_frame(const FitCase& fit_case, double settle_s) {
  std::size_t first = 0;
  while (first < fit_case.commands.frames() &&
         fit_case.commands.time_s(first) - fit_case.commands.start_s() < settle_s - 1e-12) {
    ++first;
  }
  return first;
}

FitnessFunction::FitnessFunction(std::shared_ptr<const RobotModel> model,
                                 std::vector<FitCase> cases, FitnessOptions options)
    : model_(std::move(model)), cases_(std::move(cases)), options_(std::move(options)) {
  const std::size_t n = model_->actuators.size();
  weights_ = options_.joint_weights.empty() ? std::vector<double>(n, 1.0) : options_.joint_weights;
  if (weights_.size() != n) throw std::invalid_argument("joint weights: one per actuated joint");
  if (!(options_.m >= 0.0)) throw std::invalid_argument("fitness exponent m must be >= 0");
  for (const auto& c : cases_) {
    if (c.commands.joints() != n || c.measured_rad.size() != c.commands.frames() * n) {
      throw std::invalid_argument("case " + c.name + ": measured angles do not match the model");
    }
    if (!(options_.imu_weight >= 0.0)) throw std::invalid_argument("imu_weight must be >= 0");
    if (scores_imu() && c.measured_imu_rad.size() != 2 * c.commands.frames()) {
      throw std::invalid_argument("case " + c.name +
                                  ": imu_weight > 0 needs imu.roll and imu.pitch in every log");
    }
    const std::size_t first = first_scored_frame(c, options_.settle_s);
    if (first >= c.commands.frames()) {
      throw std::invalid_argument("case " + c.name + ": settle_s covers the whole log");
    }
    first_scored_frame_.push_back(first);
  }
}

CaseScore FitnessFunction::score_case(std::size_t c, const ParameterSet& parameters,
                                      double finished_fitness, double stop_threshold,
                                      RolloutResult& result, bool& stopped) const {
  const std::size_t n = model_->actuators.size();
  const FitCase& fit_case = cases_[c];
  ParameterSet set = parameters;
  for (const auto& [index, value] : fit_case.parameter_overrides) set.set(index, value);
  const std::size_t first = first_scored_frame_[c];
  const double t_max = static_cast<double>(fit_case.commands.frames() - first);
  const double t_max_power = std::pow(t_max, options_.m);
  CaseScore score;
  score.frames_requested = fit_case.commands.frames() - first;
  stopped = false;
  // Accumulates the error frame by frame; asks the rollout to stop once the lower bound of
  // the final fitness reaches the threshold.
  const FrameObserver observer = [&](const RolloutResult& partial, std::size_t frame) {
    if (frame < first) return true;
    const double* sim = &partial.measured_rad[frame * n];
    const double* real = &fit_case.measured_rad[frame * n];
    for (std::size_t j = 0; j < n; ++j) {
      score.squared_error_rad2 += weights_[j] * frame_error(real[j] - sim[j]);
    }
    if (scores_imu()) {
      const double roll = fit_case.measured_imu_rad[2 * frame] - partial.imu_roll_rad[frame];
      const double pitch = fit_case.measured_imu_rad[2 * frame + 1] - partial.imu_pitch_rad[frame];
      score.squared_error_rad2 += options_.imu_weight * (frame_error(roll) + frame_error(pitch));
    }
    ++score.frames;
    if (std::isfinite(stop_threshold) &&
        finished_fitness + score.squared_error_rad2 / t_max_power >= stop_threshold) {
      stopped = true;
      return false;
    }
    return true;
  };
  result = run_rollout(*model_, set, fit_case.commands, fit_case.options, observer);
  score.end = result.end;
  score.end_detail = result.end_detail;
  if (stopped) {
    score.fitness = score.squared_error_rad2 / t_max_power;
  } else if (result.end == RolloutEnd::kModelError || result.end == RolloutEnd::kDiverged ||
             score.frames == 0) {
    // Failure is a score: the worst one.
    score.fitness = std::numeric_limits<double>::infinity();
  } else {
    score.fitness =
        score.squared_error_rad2 / std::pow(static_cast<double>(score.frames), options_.m);
  }
  return score;
}

FitnessBreakdown FitnessFunction::evaluate(const ParameterSet& parameters, double stop_threshold,
                                           std::vector<RolloutResult>* rollouts,
                                           int threads) const {
  FitnessBreakdown out;
  const std::size_t count = cases_.size();
  if (threads > 1 && count > 1 && !std::isfinite(stop_threshold)) {
    // Nothing stops early, so the cases are independent: simulate them at once and add them
    // up in order, as the serial loop below does.
    std::vector<CaseScore> scores(count);
    std::vector<RolloutResult> results(count);
    ensure_ode_ready();  // the process-wide part, before the workers start
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads)
    for (long c = 0; c < static_cast<long>(count); ++c) {
      ensure_ode_ready();  // this worker's own ODE data
      bool stopped = false;
      const auto i = static_cast<std::size_t>(c);
      scores[i] = score_case(i, parameters, 0.0, stop_threshold, results[i], stopped);
    }
    for (std::size_t c = 0; c < count; ++c) {
      out.fitness += scores[c].fitness;
      out.cases.push_back(std::move(scores[c]));
      if (rollouts != nullptr) rollouts->push_back(std::move(results[c]));
    }
    return out;
  }
  double finished_fitness = 0.0;  // Σ of the cases already completed
  for (std::size_t c = 0; c < count; ++c) {
    RolloutResult result;
    bool stopped = false;
    CaseScore score = score_case(c, parameters, finished_fitness, stop_threshold, result, stopped);
    if (stopped) {
      out.fitness = finished_fitness + score.fitness;
      out.stopped_early = true;
      out.cases.push_back(std::move(score));
      if (rollouts != nullptr) rollouts->push_back(std::move(result));
      return out;
    }
    finished_fitness += score.fitness;
    out.cases.push_back(std::move(score));
    if (rollouts != nullptr) rollouts->push_back(std::move(result));
  }
  out.fitness = finished_fitness;
  return out;
}

void FitnessFunction::simulated_channels(const RolloutResult& result, std::size_t frame,
                                         double* out) const {
  const std::size_t n = weights_.size();
  for (std::size_t j = 0; j < n; ++j) {
    out[j] = std::sqrt(weights_[j]) * result.measured_rad[frame * n + j];
  }
  if (scores_imu()) {
    const double w = std::sqrt(options_.imu_weight);
    out[n] = w * result.imu_roll_rad[frame];
    out[n + 1] = w * result.imu_pitch_rad[frame];
  }
}

void FitnessFunction::measured_channels(std::size_t c, std::size_t frame, double* out) const {
  const FitCase& fit_case = cases_[c];
  const std::size_t n = weights_.size();
  for (std::size_t j = 0; j < n; ++j) {
    out[j] = std::sqrt(weights_[j]) * fit_case.measured_rad[frame * n + j];
  }
  if (scores_imu()) {
    const double w = std::sqrt(options_.imu_weight);
    out[n] = w * fit_case.measured_imu_rad[2 * frame];
    out[n + 1] = w * fit_case.measured_imu_rad[2 * frame + 1];
  }
}

double FitnessFunction::channel_residual(std::size_t channel, double difference) const {
  if (!options_.absolute_error) return difference;
  // difference = √w·e, so √w·|difference| = w·|e|, the frame's term of the error sum.
  const std::size_t n = weights_.size();
  const double root_weight = std::sqrt(channel < n ? weights_[channel] : options_.imu_weight);
  const double magnitude = std::sqrt(root_weight * std::fabs(difference));
  return difference < 0.0 ? -magnitude : magnitude;
}

std::string FitnessFunction::channel_name(std::size_t channel) const {
  const std::size_t n = weights_.size();
  if (channel < n) return model_->actuators[channel].name;
  return channel == n ? "imu.roll" : "imu.pitch";
}

}  // namespace motoflex
