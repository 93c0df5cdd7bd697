#pragma once

// Internal to src/effects/: the linearised view of a fit's residual that both the effect
// ranking (effect_signature.cpp) and the open-ended term discovery (term_discovery.cpp) regress
// on: the residual of the current fit, the response of the simulated channels to a probe step,
// and the fit's own Jacobian (one probe per free parameter).

#include <Eigen/Dense>
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

// The normal equations of a least-squares fit of the residual by `columns` columns: Gram matrix
// Σ v vᵀ and Σ v·r over the residual's scored rows, with v_a = value(a, case, row, channel)
// (row = frame·channels + channel).
struct NormalEquations {
  Eigen::MatrixXd gram;
  Eigen::VectorXd rhs;
};

template <class ColumnValue>
NormalEquations normal_equations(const Residual& residual, std::size_t columns,
                                 const ColumnValue& value) {
  const auto k = static_cast<Eigen::Index>(columns);
  NormalEquations out{Eigen::MatrixXd::Zero(k, k), Eigen::VectorXd::Zero(k)};
  std::vector<double> v(columns);
  for (std::size_t c = 0; c < residual.r_rad.size(); ++c) {
    for (std::size_t f = residual.first_frame[c]; f < residual.end_frame[c]; ++f) {
      for (std::size_t i = 0; i < residual.channels; ++i) {
        const std::size_t row = f * residual.channels + i;
        for (std::size_t a = 0; a < columns; ++a) v[a] = value(a, c, row, i);
        for (std::size_t a = 0; a < columns; ++a) {
          if (v[a] == 0.0) continue;
          const auto ia = static_cast<Eigen::Index>(a);
          out.rhs(ia) += v[a] * residual.r_rad[c][row];
          for (std::size_t b = a; b < columns; ++b) {
            out.gram(ia, static_cast<Eigen::Index>(b)) += v[a] * v[b];
          }
        }
      }
    }
  }
  for (Eigen::Index a = 0; a < k; ++a) {
    for (Eigen::Index b = 0; b < a; ++b) out.gram(a, b) = out.gram(b, a);
  }
  return out;
}

// (G + ridge·I) β̂ = b in standardised units (each column scaled to unit norm, so `ridge` is
// relative): returns β in the original units and, in `reduction`, the fall of the residual sum
// of squares the fit predicts, 2β̂·b − β̂ᵀ(G + ridge·I)β̂ (standardised; the same number).
Eigen::VectorXd standardised_solve(const Eigen::MatrixXd& gram, const Eigen::VectorXd& rhs,
                                   double ridge, double* reduction = nullptr);

}  // namespace motoflex::detail
