// The flat-direction scan of the LM polish (src/fit/flat_direction_scan.hpp) on analytic
// fitness functions: which columns count as flat, and that a scan makes only the one move that
// lowers F most, so a parameter that is flat only because another one locks the joint is not
// parked at an arbitrary bound along with the lock.

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "flat_direction_scan.hpp"

namespace {

using motoflex::detail::best_flat_line_move;
using motoflex::detail::flat_columns;

TEST(FlatDirectionScan, FlatColumnsAreThoseWithoutInformation) {
  // 3 rows x 3 columns, row-major: column 1 is zero, column 2 is 1e-12 of column 0.
  const std::vector<double> jacobian = {1.0,  0.0, 1e-12,  //
                                        2.0,  0.0, 0.0,    //
                                        -2.0, 0.0, 0.0};
  EXPECT_EQ(flat_columns(jacobian, 3, 3), (std::vector<std::size_t>{1, 2}));
  EXPECT_EQ(flat_columns(jacobian, 3, 3, 1e-15), (std::vector<std::size_t>{1}));
  EXPECT_EQ(flat_columns(std::vector<double>(6, 0.0), 2, 3), (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_THROW(flat_columns(jacobian, 2, 3), std::invalid_argument);
}

// x[0]: a dry friction (0..10); at 5 and above it locks the joint, and then x[1] (a spring,
// 0..10) does nothing but round-off: F falls by 1e-12 per unit of it. Unlocked, F is
// (x0 - 1)^2 + (x1 - 3)^2, the truth at (1, 3).
double locked_joint_fitness(const std::vector<double>& x) {
  if (x[0] >= 5.0) return 20.0 - 1e-12 * x[1];
  return (x[0] - 1.0) * (x[0] - 1.0) + (x[1] - 3.0) * (x[1] - 3.0);
}

TEST(FlatDirectionScan, OnlyTheMoveThatLowersFMostIsMade) {
  const std::vector<double> lower = {0.0, 0.0}, upper = {10.0, 10.0};
  const std::vector<double> x = {10.0, 2.5};  // locked
  const auto move = best_flat_line_move(lower, upper, x, locked_joint_fitness(x), {0, 1}, 11,
                                        locked_joint_fitness);
  ASSERT_TRUE(move.found);
  EXPECT_EQ(move.index, 0u);   // the friction, not the spring that is flat because of it
  EXPECT_EQ(move.value, 1.0);  // grid 0, 1, ..., 10: F = 0.25 at x0 = 1
  EXPECT_DOUBLE_EQ(move.fitness, 0.25);
  EXPECT_EQ(move.evaluations, 21u);  // 11 points each; x0 = 10 is on the grid and known
}

TEST(FlatDirectionScan, NoMoveWhenNoPointLowersF) {
  const std::vector<double> lower = {0.0, 0.0}, upper = {10.0, 10.0};
  const std::vector<double> x = {1.0, 3.0};  // the optimum
  const auto move = best_flat_line_move(lower, upper, x, locked_joint_fitness(x), {0, 1}, 5,
                                        locked_joint_fitness);
  EXPECT_FALSE(move.found);
  EXPECT_EQ(move.fitness, 0.0);
  EXPECT_EQ(move.evaluations, 10u);
  EXPECT_THROW(best_flat_line_move(lower, upper, x, 0.0, {0}, 2, locked_joint_fitness),
               std::invalid_argument);
  EXPECT_THROW(best_flat_line_move(lower, upper, x, 0.0, {2}, 3, locked_joint_fitness),
               std::invalid_argument);
}

}  // namespace
