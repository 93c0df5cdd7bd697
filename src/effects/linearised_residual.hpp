#pragma once

// Internal to src/effects/: the linearised view of a fit's residual that both the effect
// ranking (effect_signature.cpp) and the open-ended term discovery (term_discovery.cpp) regress
// on: the residual of the current fit, the response of the simulated channels to a probe step,
// and the fit's own Jacobian (one probe per free parameter).

#include <cstddef>
#include <vector>

#include "motoflex/fit/fit_config.hpp"

namespace motoflex::detail {

// The residual of the current fit: measured − simulated channels (the fitness's: the joint
// encoders, and the IMU when the fit scores it; see FitnessFunction::channels) per case,
// frame-major, with the frames that count (scored and simulated).
struct Residual {
  std::vector<std::vector<double>> r_rad;    // per case
  std::vector<std::vector<double>> sim_rad;  // per case: simulated channels of the fit
  std::vector<std::size_t> first_frame;      // per case
  std::vector<std::size_t> end_frame;        // per case: frames the fit simulated
  std::size_t channels = 0;
  double rss = 0.0;
  std::size_t samples = 0;
  // A smooth residual carries far fewer independent samples than frames: with lag-1
  // autocorrelation ρ, N_eff = N·(1 − ρ)/(1 + ρ) (an AR(1) model of the residual).
  double effective_samples = 0.0;
};

Residual residual_of(const FitnessFunction& fitness, const ParameterSet& current);

// Search coordinate, probe step and bounds of one probed direction.
struct Direction {
  double current = 0.0, step = 0.0, lower = 0.0, upper = 0.0;
};

Direction direction(double current, double lower, double upper, double fraction);

// d(simulated channels) for one probe set: probe − current, per case, frame-major; frames the
// probe did not reach are 0 (no information).
std::vector<std::vector<double>> response(const FitnessFunction& fitness, const ParameterSet& set,
                                          const Residual& residual);

// The sensitivity of the simulated channels to each free parameter of the current fit (one
// probe each): the directions a refit can already move in.
struct FitJacobian {
  std::vector<std::vector<std::vector<double>>> columns;  // per free parameter
  std::vector<Direction> directions;
};

FitJacobian fit_jacobian(const FitConfig& config, const ParameterSet& current,
                         const Residual& residual, int threads);

}  // namespace motoflex::detail
