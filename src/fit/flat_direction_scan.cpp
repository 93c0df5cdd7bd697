#include "flat_direction_scan.hpp"

#include <algorithm>
#include <cmath>
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

FlatLineMove best_flat_line_move(const std::vector<double>& lower, const std::vector<double>& upper,
                                 const std::vector<double>& x, double fitness,
                                 const std::vector<std::size_t>& flat, std::size_t points,
                                 const FitnessAt& measure) {
  if (points < 3) throw std::invalid_argument("best_flat_line_move: points must be >= 3");
  FlatLineMove best;
  best.fitness = fitness;
  for (const std::size_t i : flat) {
    if (i >= x.size() || i >= lower.size() || i >= upper.size()) {
      throw std::invalid_argument("best_flat_line_move: a flat index is out of range");
    }
    std::vector<double> trial = x;
    for (std::size_t k = 0; k < points; ++k) {
      const double share = static_cast<double>(k) / static_cast<double>(points - 1);
      trial[i] = k + 1 == points ? upper[i] : lower[i] + share * (upper[i] - lower[i]);
      if (trial[i] == x[i]) continue;  // F there is known
      const double f = measure(trial);
      ++best.evaluations;
      if (f < best.fitness) {
        best.found = true;
        best.index = i;
        best.value = trial[i];
        best.fitness = f;
      }
    }
  }
  return best;
}

FlatScanResult scan_flat_directions(const ParameterSpace& space, const std::vector<double>& x,
                                    double fitness, const std::vector<std::size_t>& flat,
                                    std::size_t points, const FitnessAt& measure) {
  const FlatLineMove best =
      best_flat_line_move(space.lower(), space.upper(), x, fitness, flat, points, measure);
  FlatScanResult out{x, fitness, std::nullopt, best.evaluations};
  if (!best.found) return out;
  out.move = FlatScanMove{space.free_parameters()[best.index].name,
                          space.to_model(best.index, x[best.index]),
                          space.to_model(best.index, best.value), fitness, best.fitness};
  out.x[best.index] = best.value;
  out.fitness = best.fitness;
  return out;
}

}  // namespace motoflex::detail
