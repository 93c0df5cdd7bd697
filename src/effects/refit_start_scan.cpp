#include "motoflex/effects/refit_start_scan.hpp"

namespace motoflex::detail {

bool scan_effect_start(const ParameterSpace& space, const std::vector<std::size_t>& indices,
                       std::size_t points,
                       const std::function<double(const std::vector<double>&)>& fitness,
                       std::vector<double>& x, double& best_fitness, bool pairs_jointly) {
  if (points < 3) return false;
  const std::vector<double> lower = space.lower();
  const std::vector<double> upper = space.upper();
  const auto grid = [&](std::size_t i, std::size_t j) {
    return lower[i] +
           (upper[i] - lower[i]) * static_cast<double>(j) / static_cast<double>(points - 1);
  };
  const auto keep_if_better = [&](std::vector<double> trial) {
    const double f = fitness(trial);
    if (f < best_fitness) {
      best_fitness = f;
      x = std::move(trial);
    }
  };
  if (pairs_jointly && indices.size() == 2) {
    const std::vector<double> held = x;
    for (std::size_t ja = 0; ja < points; ++ja) {
      for (std::size_t jb = 0; jb < points; ++jb) {
        std::vector<double> trial = held;
        trial[indices[0]] = grid(indices[0], ja);
        trial[indices[1]] = grid(indices[1], jb);
        keep_if_better(std::move(trial));
      }
    }
    return true;
  }
  for (const std::size_t i : indices) {
    for (std::size_t j = 0; j < points; ++j) {
      std::vector<double> trial = x;
      trial[i] = grid(i, j);
      keep_if_better(std::move(trial));
    }
  }
  return false;
}

}  // namespace motoflex::detail
