#pragma once

// Internal to FitSession: the fit as a least-squares problem. The residual vector holds, for
// every training log c, scored frame t and scored channel k (joints, then the IMU when scored),
//
//   r = √w_k (q_real − q_sim) / √(T_c^m),   T_c = the log's scored frames,
//
// so Σ r² is the fitness F of a run whose rollouts all complete. Coordinates are the strategy's
// (log where the free parameter is searched on a log scale).

#include <cstdint>
#include <vector>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_spec.hpp"

namespace motoflex::detail {

class FitResiduals {
 public:
  // `threads` > 1 simulates the logs (residuals) or the Jacobian's points in parallel (OpenMP);
  // the numbers do not depend on it.
  FitResiduals(const FitConfig& config, int threads);

  std::size_t size() const { return size_; }  // N
  std::size_t dimension() const;              // p
  // The layout of r: per training log its scored frames, each frame `channels()` residuals.
  const std::vector<std::size_t>& frames_per_case() const { return frames_; }
  std::size_t channels() const;

  // r(x) into `out` (size()); false when a rollout fails or ends before its log does (the
  // residuals are then not comparable).
  bool evaluate(const std::vector<double>& x, double* out) const;

  // The finite-difference Jacobian at x (row-major N × p), h_i = step · (upper_i − lower_i).
  // Central: column i from x ± h_i e_i; one-sided (with r(x) = `r0`) where x ± h_i leaves the
  // bounds or its rollout fails. Forward: column i from x + h_i e_i and `r0`, or from x − h_i e_i
  // where x + h_i leaves the bounds or its rollout fails (a second pass over those columns
  // only). Either way a zero column where neither side works. Returns the rollout sets
  // simulated (each a pass over all logs).
  // `nonlinearity` (may be null) gets, per column with both probes, how far r is from linear
  // over ±h: s_i = ‖d₊ + d₋‖ / ‖d₊ − d₋‖, d± = r(x ± h_i e_i) − r(x), the second-order change
  // against the first-order one (b·h/a for r = a·δ + b·δ²; near 1 where r is not smooth at
  // the scale h, e.g. a chaotic walk); NaN for a one-sided or zero column.
  std::uint64_t jacobian(const std::vector<double>& x, const std::vector<double>& r0, double step,
                         std::vector<double>& out, FiniteDifferences scheme,
                         std::vector<double>* nonlinearity) const;

 private:
  // r at each point into `r` (`ok`: the rollouts completed), the points in parallel; returns
  // the rollout sets simulated.
  std::uint64_t evaluate_points(const std::vector<std::vector<double>>& points,
                                std::vector<std::vector<double>>& r, std::vector<char>& ok) const;

  const FitConfig& config_;
  int threads_;
  std::size_t size_ = 0;
  std::vector<std::size_t> first_frame_;  // per case
  std::vector<std::size_t> frames_;       // per case: scored frames
  std::vector<double> scale_;             // per case: 1/√(T^m)
};

}  // namespace motoflex::detail
