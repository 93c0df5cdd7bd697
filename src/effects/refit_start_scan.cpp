#include "motoflex/effects/refit_start_scan.hpp"

namespace motoflex::detail {

void scan_effect_start(const ParameterSpace& space, const std::vector<std::size_t>& indices,
                       std::size_t points,
                       const std::function<double(const std::vector<double>&)>& fitness,
                       std::vector<double>& x, double& best_fitness) {
  if (points < 3) return;
  const std::vector<double> lower = space.lower();
  const std::vector<double> upper = space.upper();
  for (const std::size_t i : indices) {
    for (std::size_t j = 0; j < points; ++j) {
      std::vector<double> trial = x;
      trial[i] = lower[i] +
                 (upper[i] - lower[i]) * static_cast<double>(j) / static_cast<double>(points - 1);
      const double f = fitness(trial);
      if (f < best_fitness) {
        best_fitness = f;
        x = std::move(trial);
      }
    }
  }
}

}  // namespace motoflex::detail
