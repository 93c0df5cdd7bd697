#pragma once

// How many independent samples a residual vector holds. Residuals of joint logs are smooth in
// time where the model is wrong (a missing effect leaves the same sign over many frames), so
// counting every residual as an independent sample makes σ²(JᵀJ)⁻¹ far too small. Under an
// AR(1) model of each channel's residual series with lag-1 autocorrelation ρ, the variance of a
// least-squares estimate along a smooth direction grows by
//
//   κ = (1 + ρ) / (1 − ρ),   N_eff = N / κ,
//
// (the loop's effect signatures use this ρ too, src/effects/linearised_residual.cpp). White
// residuals (ρ ≤ 0) leave κ = 1: a model that explains the data up to sensor noise keeps its
// nominal intervals.

#include <cstddef>
#include <vector>

namespace motoflex {

struct ResidualAutocorrelation {
  double lag1 = 0.0;       // ρ, pooled over every channel of every series
  double inflation = 1.0;  // κ, the factor on the covariance
  double effective = 0.0;  // N_eff = N / κ
};

// `residuals` holds consecutive series (one per log), each `frames_per_series[s]` frames of
// `channels` values, frame-major: r[(t·channels) + k] within a series. ρ = Σ r_t,k r_t−1,k / Σ r²
// over all series and channels (lag in frames, never across two series). ρ is capped at
// 1 − 1e−6. Throws std::invalid_argument when the layout does not cover `residuals` exactly.
ResidualAutocorrelation residual_autocorrelation(const std::vector<double>& residuals,
                                                 const std::vector<std::size_t>& frames_per_series,
                                                 std::size_t channels);

}  // namespace motoflex
