#pragma once

#include <cstdint>
#include <limits>

namespace motoflex_es {

// Stops a search that no longer improves on its best point, whoever found it: the strategy's
// own samples or an incumbent handed in before the search (evaluate_incumbent). A strategy's
// own stall tests (CMA-ES tol_stall, stagnation) watch its samples only: a CMA-ES refit that
// starts at a good incumbent with a wide σ keeps improving its own, far worse, samples and
// spends its whole budget without ever reaching the incumbent.
//
// The anchor is the best fitness at the last "real" improvement, one that lowered it by more
// than relative_tolerance·|anchor|, and the evaluation count at that moment. The search has
// stalled once window_evaluations more evaluations have passed without such an improvement.
// The two numbers are the whole state, so a checkpoint that stores them resumes exactly.
class ImprovementStall {
 public:
  ImprovementStall(std::uint64_t window_evaluations, double relative_tolerance);

  // Feeds the best fitness so far after `evaluations` evaluations (call it after every
  // generation, the incumbent's included); returns whether the search has stalled.
  bool update(double best_fitness, std::uint64_t evaluations);
  bool stalled() const { return stalled_; }
  bool enabled() const { return window_ > 0; }

  double anchor_fitness() const { return anchor_fitness_; }
  std::uint64_t anchor_evaluations() const { return anchor_evaluations_; }
  // Restores the state a checkpoint stored.
  void restore(double anchor_fitness, std::uint64_t anchor_evaluations);

 private:
  std::uint64_t window_ = 0;  // 0 = never stalls
  double relative_tolerance_ = 0.0;
  double anchor_fitness_ = std::numeric_limits<double>::infinity();
  std::uint64_t anchor_evaluations_ = 0;
  bool stalled_ = false;
};

}  // namespace motoflex_es
