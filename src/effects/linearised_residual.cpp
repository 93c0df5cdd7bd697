#include "linearised_residual.hpp"

#include <omp.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "motoflex/fit/residual_autocorrelation.hpp"

namespace motoflex::detail {
namespace {

constexpr double kProbeFraction = 0.05;     // probe step of the fit's own parameters (of the width)
constexpr double kMaxResidualLag1 = 0.999;  // N_eff ≥ N/1999

// The simulated channels of frames [0, frames_completed) of a rollout, frame-major.
std::vector<double> simulated_channels(const FitnessFunction& fitness, const RolloutResult& rollout,
                                       std::size_t frames) {
  const std::size_t k = fitness.channels();
  std::vector<double> out(frames * k, 0.0);
  for (std::size_t f = 0; f < std::min(frames, rollout.frames_completed); ++f) {
    fitness.simulated_channels(rollout, f, &out[f * k]);
  }
  return out;
}

}  // namespace

Residual residual_of(const FitnessFunction& fitness, const ParameterSet& current) {
  std::vector<RolloutResult> rollouts;
  fitness.evaluate(current, std::numeric_limits<double>::infinity(), &rollouts);
  Residual out;
  out.channels = fitness.channels();
  const std::size_t k = out.channels;
  std::vector<double> measured(k);
  std::vector<double> all;  // every case's r, frame-major, for the autocorrelation
  std::vector<std::size_t> frames_per_case;
  for (std::size_t c = 0; c < fitness.cases().size(); ++c) {
    const FitCase& fit_case = fitness.cases()[c];
    const RolloutResult& rollout = rollouts[c];
    const std::size_t frames = fit_case.commands.frames();
    const std::size_t first = first_scored_frame(fit_case, fitness.options().settle_s);
    const std::size_t end = rollout.frames_completed;
    std::vector<double> sim = simulated_channels(fitness, rollout, frames);
    std::vector<double> r(frames * k, 0.0);
    for (std::size_t f = first; f < end; ++f) {
      fitness.measured_channels(c, f, measured.data());
      for (std::size_t i = 0; i < k; ++i) {
        r[f * k + i] = measured[i] - sim[f * k + i];
        out.rss += r[f * k + i] * r[f * k + i];
        ++out.samples;
      }
    }
    // Frames outside [first, end) hold 0 and add nothing to either sum of the autocorrelation.
    all.insert(all.end(), r.begin(), r.end());
    frames_per_case.push_back(frames);
    out.r_rad.push_back(std::move(r));
    out.sim_rad.push_back(std::move(sim));
    out.first_frame.push_back(first);
    out.end_frame.push_back(end);
  }
  const double rho =
      std::clamp(residual_autocorrelation(all, frames_per_case, k).lag1, 0.0, kMaxResidualLag1);
  out.effective_samples =
      std::max(2.0, static_cast<double>(out.samples) * (1.0 - rho) / (1.0 + rho));
  return out;
}

Direction direction(double current, double lower, double upper, double fraction) {
  Direction d{std::clamp(current, lower, upper), fraction * (upper - lower), lower, upper};
  if (d.current + d.step > upper || d.current + d.step < lower) d.step = -d.step;
  return d;
}

std::vector<std::vector<double>> response(const FitnessFunction& fitness, const ParameterSet& set,
                                          const Residual& residual) {
  std::vector<RolloutResult> rollouts;
  fitness.evaluate(set, std::numeric_limits<double>::infinity(), &rollouts);
  const std::size_t k = residual.channels;
  std::vector<double> probe(k);
  std::vector<std::vector<double>> out(residual.r_rad.size());
  for (std::size_t c = 0; c < out.size(); ++c) {
    out[c].assign(residual.r_rad[c].size(), 0.0);
    const std::size_t end = std::min(residual.end_frame[c], rollouts[c].frames_completed);
    for (std::size_t f = residual.first_frame[c]; f < end; ++f) {
      fitness.simulated_channels(rollouts[c], f, probe.data());
      for (std::size_t i = 0; i < k; ++i) {
        out[c][f * k + i] = probe[i] - residual.sim_rad[c][f * k + i];
      }
    }
  }
  return out;
}

Eigen::VectorXd standardised_solve(const Eigen::MatrixXd& gram, const Eigen::VectorXd& rhs,
                                   double ridge, double* reduction) {
  const Eigen::Index k = rhs.size();
  Eigen::VectorXd scale(k), b(k);
  Eigen::MatrixXd g(k, k);
  for (Eigen::Index i = 0; i < k; ++i) scale(i) = std::sqrt(std::max(gram(i, i), 1e-300));
  for (Eigen::Index i = 0; i < k; ++i) {
    b(i) = rhs(i) / scale(i);
    for (Eigen::Index j = 0; j < k; ++j) g(i, j) = gram(i, j) / (scale(i) * scale(j));
  }
  g.diagonal().array() += ridge;
  const Eigen::VectorXd beta_std = g.ldlt().solve(b);
  if (reduction != nullptr) *reduction = 2.0 * beta_std.dot(b) - beta_std.dot(g * beta_std);
  return beta_std.cwiseQuotient(scale);
}

FitJacobian fit_jacobian(const FitConfig& config, const ParameterSet& current,
                         const Residual& residual, int threads) {
  const ParameterSpace& space = *config.space;
  FitJacobian out;
  out.columns.resize(space.dimension());
  for (std::size_t i = 0; i < space.dimension(); ++i) {
    const FreeParameter& p = space.free_parameters()[i];
    out.directions.push_back(direction(space.to_search(i, current.get(p.targets.front())),
                                       space.lower()[i], space.upper()[i], kProbeFraction));
  }
  const int n = static_cast<int>(space.dimension());
#pragma omp parallel for schedule(dynamic) num_threads(std::max(threads, 1))
  for (int i = 0; i < n; ++i) {
    ParameterSet moved = current;
    const FreeParameter& p = space.free_parameters()[i];
    const Direction& d = out.directions[i];
    for (const auto& target : p.targets) moved.set(target, space.to_model(i, d.current + d.step));
    out.columns[i] = response(*config.train, moved, residual);
  }
  return out;
}

}  // namespace motoflex::detail
