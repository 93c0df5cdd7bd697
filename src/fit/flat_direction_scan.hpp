#pragma once

// Internal to the LM polish (`polish: {flat_scan: N}`): a line scan along the parameters LM
// cannot move. Where a parameter's Jacobian column is zero (a dry friction that never slips, a
// limit that never binds, a clutch that stays locked) LM gets no direction along it and stays,
// even when the fitness is lower elsewhere on that line: nao_paper's first stage ended with the
// flex joints' friction at its upper bound, locking them, where F on the first 2 s was 4 % above
// its value with the friction near zero. Each such parameter is tried at N evenly spaced points
// across its bounds (the strategy's coordinates, log where it searches so), the others held,
// one parameter after the other, and moved to its best point when that lowers F.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "motoflex/fit/fit_config.hpp"

namespace motoflex::detail {

// The columns of a row-major N × p Jacobian that carry no information: norm at most
// `relative` times the largest column's (all of them when every column is zero).
std::vector<std::size_t> flat_columns(const std::vector<double>& jacobian, std::size_t rows,
                                      std::size_t columns, double relative = 1e-9);

// One parameter the scan moved.
struct FlatScanMove {
  std::string parameter;
  double from = 0.0;  // model units
  double to = 0.0;
  double fitness_before = 0.0;
  double fitness_after = 0.0;
};

struct FlatScanResult {
  std::vector<double> x;  // search coordinates
  double fitness = 0.0;   // F at x, measured as the strategy measures it
  std::vector<FlatScanMove> moves;
  std::uint64_t rollouts = 0;  // passes over all training logs
};

// Scans each of `flat` (indices into x) at `points` (>= 3) values from its lower to its upper
// bound, from x with fitness F(x) = `fitness`. `on_move` hears each move as it is made.
FlatScanResult scan_flat_directions(const FitConfig& config, const std::vector<double>& x,
                                    double fitness, const std::vector<std::size_t>& flat,
                                    std::size_t points,
                                    const std::function<void(const FlatScanMove&)>& on_move = {});

}  // namespace motoflex::detail
