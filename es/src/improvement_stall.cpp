#include "motoflex_es/improvement_stall.hpp"

#include <cmath>
#include <stdexcept>

namespace motoflex_es {

ImprovementStall::ImprovementStall(std::uint64_t window_evaluations, double relative_tolerance)
    : window_(window_evaluations), relative_tolerance_(relative_tolerance) {
  if (!(relative_tolerance >= 0.0) || !std::isfinite(relative_tolerance)) {
    throw std::invalid_argument("ImprovementStall: relative_tolerance must be finite and >= 0");
  }
}

bool ImprovementStall::update(double best_fitness, std::uint64_t evaluations) {
  if (window_ == 0) return false;
  // A first finite value starts the window; NaN and +inf never improve (a search that has found
  // nothing valid for a whole window has stalled too).
  const bool improved =
      std::isfinite(best_fitness) &&
      (!std::isfinite(anchor_fitness_) ||
       best_fitness < anchor_fitness_ - relative_tolerance_ * std::abs(anchor_fitness_));
  if (improved) {
    anchor_fitness_ = best_fitness;
    anchor_evaluations_ = evaluations;
  }
  stalled_ = evaluations >= anchor_evaluations_ + window_;
  return stalled_;
}

void ImprovementStall::restore(double anchor_fitness, std::uint64_t anchor_evaluations) {
  anchor_fitness_ = anchor_fitness;
  anchor_evaluations_ = anchor_evaluations;
  stalled_ = false;
}

}  // namespace motoflex_es
