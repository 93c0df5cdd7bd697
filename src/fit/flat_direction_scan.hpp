#pragma once

// Internal to the LM polish (`polish: {flat_scan: N}`): a line scan along the parameters LM
// cannot move. Where a parameter's Jacobian column is zero (a dry friction that never slips, a
// limit that never binds, a clutch that stays locked) LM gets no direction along it and stays,
// even when the fitness is lower elsewhere on that line: nao_paper's first stage ended with the
// flex joints' friction at its upper bound, locking them, where F on the first 2 s was 4 % above
// its value with the friction near zero. Each such parameter is tried at N evenly spaced points
// across its bounds (the strategy's coordinates, log where it searches so), the others held, all
// from the same point; only the one move that lowers F most is made. A locked joint makes its
// companions flat too (the locked flex joints' spring does nothing), and where F moves along
// them it moves by noise: moving them with the lock would park them at arbitrary values. Once
// the lock is gone LM sees them again, and the next scan looks at what is still flat.

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/fit/parameter_space.hpp"

namespace motoflex::detail {

// The columns of a row-major N × p Jacobian that carry no information: norm at most
// `relative` times the largest column's (all of them when every column is zero).
std::vector<std::size_t> flat_columns(const std::vector<double>& jacobian, std::size_t rows,
                                      std::size_t columns, double relative = 1e-9);

// F at a point in search coordinates (infinite where a rollout fails).
using FitnessAt = std::function<double(const std::vector<double>&)>;

// The best single move along one of `flat` (indices into x): each is tried at `points` (>= 3)
// values from lower[i] to upper[i], the other coordinates held at x, with F(x) = `fitness`.
struct FlatLineMove {
  bool found = false;     // some point lowered F
  std::size_t index = 0;  // which coordinate
  double value = 0.0;     // its new value (search coordinates)
  double fitness = 0.0;   // F there
  std::uint64_t evaluations = 0;
};
FlatLineMove best_flat_line_move(const std::vector<double>& lower, const std::vector<double>& upper,
                                 const std::vector<double>& x, double fitness,
                                 const std::vector<std::size_t>& flat, std::size_t points,
                                 const FitnessAt& measure);

// The parameter the scan moved.
struct FlatScanMove {
  std::string parameter;
  double from = 0.0;  // model units
  double to = 0.0;
  double fitness_before = 0.0;
  double fitness_after = 0.0;
};

struct FlatScanResult {
  std::vector<double> x;             // search coordinates
  double fitness = 0.0;              // F at x, as `measure` gives it
  std::optional<FlatScanMove> move;  // none when no point lowered F
  std::uint64_t rollouts = 0;        // passes over all training logs
};

// best_flat_line_move within the bounds of `space`, the move named in model units.
FlatScanResult scan_flat_directions(const ParameterSpace& space, const std::vector<double>& x,
                                    double fitness, const std::vector<std::size_t>& flat,
                                    std::size_t points, const FitnessAt& measure);

}  // namespace motoflex::detail
