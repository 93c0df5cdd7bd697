#include "support_refinement.hpp"

#include <algorithm>

namespace motoflex::detail {
namespace {

constexpr double kInitialDamping = 1e-3;  // λ of (JᵀJ + λ·diag JᵀJ) δ = Jᵀr (Marquardt's scaling)
constexpr double kDampingFactor = 10.0;
constexpr int kTriesPerIteration = 4;  // rejected steps raise λ before the refinement stops

double clamp_to(const RefinedCoordinate& c, double value) {
  return std::clamp(value, c.lower, c.upper);
}

// The parameter set of `current` with the coordinates at `values`.
ParameterSet with_coordinates(const FitConfig& config, const ParameterSet& current,
                              const std::vector<RefinedCoordinate>& coordinates,
                              const std::vector<double>& values) {
  ParameterSet out = current;
  const ParameterSpace& space = *config.space;
  for (std::size_t j = 0; j < coordinates.size(); ++j) {
    const RefinedCoordinate& c = coordinates[j];
    const double model_value = c.term ? values[j] : space.to_model(c.free_index, values[j]);
    for (const std::string& target : c.targets) out.set(target, model_value);
  }
  return out;
}

// The Jacobian of the simulated channels at `values` (one probe per coordinate), as normal
// equations against the residual there.
NormalEquations linearise(const FitConfig& config, const ParameterSet& current,
                          const std::vector<RefinedCoordinate>& coordinates,
                          const std::vector<double>& values, const Residual& residual) {
  const std::size_t n = coordinates.size();
  std::vector<std::vector<std::vector<double>>> columns(n);
  std::vector<double> steps(n);
  for (std::size_t j = 0; j < n; ++j) {
    const RefinedCoordinate& c = coordinates[j];
    double step = c.step;
    if (values[j] + step > c.upper) step = -step;
    std::vector<double> moved = values;
    moved[j] = clamp_to(c, values[j] + step);
    steps[j] = moved[j] - values[j];
    columns[j] =
        response(*config.train, with_coordinates(config, current, coordinates, moved), residual);
  }
  return normal_equations(residual, n,
                          [&](std::size_t a, std::size_t c, std::size_t row, std::size_t) {
                            return steps[a] != 0.0 ? columns[a][c][row] / steps[a] : 0.0;
                          });
}

}  // namespace

RefinedSupport refine_support(const FitConfig& config, const ParameterSet& current,
                              const std::vector<RefinedCoordinate>& start, double start_fitness,
                              int iterations) {
  RefinedSupport out;
  for (const RefinedCoordinate& c : start) out.values.push_back(clamp_to(c, c.value));
  out.fitness = start_fitness;
  const std::size_t cases = config.train->cases().size();
  double lambda = kInitialDamping;
  for (int it = 0; it < iterations; ++it) {
    const ParameterSet here = with_coordinates(config, current, start, out.values);
    const Residual residual = residual_of(*config.train, here);
    const NormalEquations l = linearise(config, current, start, out.values, residual);
    out.rollouts += (start.size() + 1) * cases;
    bool accepted = false;
    for (int attempt = 0; attempt < kTriesPerIteration && !accepted; ++attempt) {
      const Eigen::VectorXd delta = standardised_solve(l.gram, l.rhs, lambda + 1e-9);
      std::vector<double> trial = out.values;
      for (std::size_t j = 0; j < start.size(); ++j) {
        trial[j] = clamp_to(start[j], trial[j] + delta(static_cast<Eigen::Index>(j)));
      }
      const double fitness =
          config.train->evaluate(with_coordinates(config, current, start, trial)).fitness;
      out.rollouts += cases;
      if (fitness < out.fitness) {
        out.values = std::move(trial);
        out.fitness = fitness;
        accepted = true;
        ++out.accepted_steps;
        lambda = std::max(lambda / kDampingFactor, 1e-9);
      } else {
        lambda *= kDampingFactor;
      }
    }
    if (!accepted) break;
  }
  return out;
}

}  // namespace motoflex::detail
