#include "flat_direction_scan.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace motoflex::detail {

std::vector<std::size_t> flat_columns(const std::vector<double>& jacobian, std::size_t rows,
                                      std::size_t columns, double relative) {
  if (jacobian.size() != rows * columns) {
    throw std::invalid_argument("flat_columns: the Jacobian is not rows x columns");
  }
  std::vector<double> norm(columns, 0.0);
  for (std::size_t r = 0; r < rows; ++r) {
    for (std::size_t c = 0; c < columns; ++c) {
      const double v = jacobian[r * columns + c];
      norm[c] += v * v;
    }
  }
  double largest = 0.0;
  for (double& n : norm) {
    n = std::sqrt(n);
    largest = std::max(largest, n);
  }
  std::vector<std::size_t> flat;
  for (std::size_t c = 0; c < columns; ++c) {
    if (norm[c] <= relative * largest) flat.push_back(c);
  }
  return flat;
}

FlatScanResult scan_flat_directions(const FitConfig& config, const std::vector<double>& x,
                                    double fitness, const std::vector<std::size_t>& flat,
                                    std::size_t points,
                                    const std::function<void(const FlatScanMove&)>& on_move) {
  if (points < 3) throw std::invalid_argument("scan_flat_directions: points must be >= 3");
  const ParameterSpace& space = *config.space;
  const std::vector<double> lower = space.lower(), upper = space.upper();
  FlatScanResult out{x, fitness, {}, 0};
  const auto measure = [&](const std::vector<double>& at) {
    ++out.rollouts;
    try {
      return config.train
          ->evaluate(space.apply(at), std::numeric_limits<double>::infinity(), nullptr,
                     config.threads)
          .fitness;
    } catch (const std::exception&) {
      return std::numeric_limits<double>::infinity();
    }
  };
  for (const std::size_t i : flat) {
    std::vector<double> trial = out.x;
    double best_value = out.x[i], best_fitness = out.fitness;
    for (std::size_t k = 0; k < points; ++k) {
      const double share = static_cast<double>(k) / static_cast<double>(points - 1);
      trial[i] = k + 1 == points ? upper[i] : lower[i] + share * (upper[i] - lower[i]);
      if (trial[i] == out.x[i]) continue;  // F there is known
      const double f = measure(trial);
      if (f < best_fitness) {
        best_fitness = f;
        best_value = trial[i];
      }
    }
    if (best_value == out.x[i]) continue;
    FlatScanMove move{space.free_parameters()[i].name, space.to_model(i, out.x[i]),
                      space.to_model(i, best_value), out.fitness, best_fitness};
    out.x[i] = best_value;
    out.fitness = best_fitness;
    if (on_move) on_move(move);
    out.moves.push_back(std::move(move));
  }
  return out;
}

}  // namespace motoflex::detail
