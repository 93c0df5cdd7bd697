// The loop refit's start scan (refit_start_scan.hpp): a parameter whose neutral value does
// nothing (a current limit far above any current) is moved to where it acts; a start already
// best is kept; coordinates not scanned are left alone.

#include "motoflex/effects/refit_start_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "motoflex/model/parameters.hpp"

namespace motoflex {
namespace {

class RefitStartScanTest : public ::testing::Test {
 protected:
  RefitStartScanTest() {
    registry_.add({"motor.current_limit_a", unit_from_parameter_name("motor.current_limit_a"),
                   1.0e3, 0.05, 1.0e3});
    registry_.add(
        {"joint.j.friction_nm", unit_from_parameter_name("joint.j.friction_nm"), 0.0, 0.0, 0.2});
  }
  // The current limit (log) and a friction (linear) both free; the scan is given only the
  // limit's coordinate.
  ParameterSpace space() const {
    std::vector<FreeParameter> free;
    free.push_back({"motor.current_limit_a", {"motor.current_limit_a"}, 0.05, 1.0e3, true, 1.0e3});
    free.push_back({"joint.j.friction_nm", {"joint.j.friction_nm"}, 0.0, 0.2, false, 0.07});
    return ParameterSpace(std::move(free), ParameterSet(registry_));
  }
  ParameterRegistry registry_;
};

// A limit above 10 A never binds (fitness 1, flat: the linearised step sees no slope); below,
// the fitness is 0.5 + (ln I/1.3)² (best at 1.3 A). x[0] is ln I (the limit is log-scaled).
double current_limit_fitness(const std::vector<double>& x) {
  const double amps = std::exp(x[0]);
  if (amps > 10.0) return 1.0;
  const double d = std::log(amps / 1.3);
  return 0.5 + d * d;
}

TEST_F(RefitStartScanTest, AParameterThatDoesNothingAtItsStartMovesToWhereItActs) {
  std::vector<double> x{std::log(398.0), 0.07};
  double best = current_limit_fitness(x);
  int calls = 0;
  detail::scan_effect_start(
      space(), {0}, 9,
      [&](const std::vector<double>& trial) {
        ++calls;
        return current_limit_fitness(trial);
      },
      x, best);
  // Nine points log-spaced over [0.05, 1000] A: ratio (2e4)^(1/8) = 3.45; the nearest to 1.3 A
  // is 0.05·3.45³ = 2.05 A (fitness 0.5 + ln(2.05/1.3)² = 0.708).
  const double amps = std::exp(x[0]);
  EXPECT_EQ(calls, 9);  // friction_nm is not scanned
  EXPECT_NEAR(amps, 0.05 * std::pow(2.0e4, 3.0 / 8.0), 1e-9);
  EXPECT_NEAR(best, 0.5 + std::pow(std::log(amps / 1.3), 2), 1e-12);
  EXPECT_LT(best, 0.75);
  EXPECT_EQ(x[1], 0.07);
}

TEST_F(RefitStartScanTest, AStartAlreadyBestIsKept) {
  std::vector<double> x{std::log(1.3), 0.07};
  double best = current_limit_fitness(x);
  detail::scan_effect_start(space(), {0}, 9, current_limit_fitness, x, best);
  EXPECT_NEAR(std::exp(x[0]), 1.3, 1e-12);
  EXPECT_EQ(best, 0.5);
  // Fewer than three points is no scan.
  std::vector<double> far{std::log(398.0), 0.07};
  double far_best = 1.0;
  detail::scan_effect_start(space(), {0}, 2, current_limit_fitness, far, far_best);
  EXPECT_EQ(far[0], std::log(398.0));
}

// Winding heating's shape: the heat capacity C (coordinate 1, log) acts only when the thermal
// resistance R_th (coordinate 0) is on, and at the start's C no R_th helps. Fitness 1 − on·g(C),
// on = 1 − e^(−R_th/20), g = exp(−ln²(C/0.1)), plus 0.1·on where g < 0.2 (heating at a C that
// does not fit costs): best near R_th = 200, C = 0.1. At the start's C = 0.5, g = e^(−2.59) =
// 0.075, so every R_th > 0 is worse (+0.025·on) and C's scan, done with R_th still 0, is flat.
double heating_fitness(const std::vector<double>& x) {
  const double rth = x[0];
  const double c = std::exp(x[1]);
  const double shape = std::exp(-std::pow(std::log(c / 0.1), 2));
  const double on = 1.0 - std::exp(-rth / 20.0);
  return 1.0 - on * shape + (rth > 0.0 && shape < 0.2 ? 0.1 * on : 0.0);
}

class PairScanTest : public ::testing::Test {
 protected:
  PairScanTest() {
    registry_.add({"motor.winding_k_per_w", unit_from_parameter_name("motor.winding_k_per_w"), 0.0,
                   0.0, 200.0});
    registry_.add({"motor.winding_heat_j_per_k",
                   unit_from_parameter_name("motor.winding_heat_j_per_k"), 0.5, 0.01, 20.0});
  }
  ParameterSpace space() const {
    std::vector<FreeParameter> free;
    free.push_back({"motor.winding_k_per_w", {"motor.winding_k_per_w"}, 0.0, 200.0, false, 0.0});
    free.push_back(
        {"motor.winding_heat_j_per_k", {"motor.winding_heat_j_per_k"}, 0.01, 20.0, true, 0.5});
    return ParameterSpace(std::move(free), ParameterSet(registry_));
  }
  ParameterRegistry registry_;
};

TEST_F(PairScanTest, OneParameterAtATimeCannotSwitchThePairOn) {
  std::vector<double> x{0.0, std::log(0.5)};
  double best = heating_fitness(x);
  ASSERT_EQ(best, 1.0);
  detail::scan_effect_start(space(), {0, 1}, 9, heating_fitness, x, best);
  // R_th's scan at C = 0.5 only adds the penalty (shape 0.075 < 0.2); C's scan at R_th = 0 is flat.
  EXPECT_EQ(x[0], 0.0);
  EXPECT_EQ(best, 1.0);
}

TEST_F(PairScanTest, TheGridOfThePairFindsWhereBothAct) {
  std::vector<double> x{0.0, std::log(0.5)};
  double best = heating_fitness(x);
  int calls = 0;
  detail::scan_effect_start(
      space(), {0, 1}, 9,
      [&](const std::vector<double>& trial) {
        ++calls;
        return heating_fitness(trial);
      },
      x, best, true);
  EXPECT_EQ(calls, 81);
  // C's grid is 0.01·2000^(k/8) J/K: k = 2 gives 0.067, k = 3 0.173; the nearer to 0.1 in log
  // terms is k = 2 (ln(0.1/0.067) = 0.40 against ln(0.173/0.1) = 0.55).
  const double c = std::exp(x[1]);
  EXPECT_NEAR(c, 0.01 * std::pow(2000.0, 2.0 / 8.0), 1e-9);
  EXPECT_EQ(x[0], 200.0);  // the largest R_th: e^(−10) of the way to fully on
  EXPECT_NEAR(best, 1.0 - (1.0 - std::exp(-10.0)) * std::exp(-std::pow(std::log(c / 0.1), 2)),
              1e-12);
  EXPECT_LT(best, 0.2);
  // A start already best is kept, as in the coordinate-wise scan.
  std::vector<double> kept{200.0, std::log(0.1)};
  double kept_best = heating_fitness(kept);
  detail::scan_effect_start(space(), {0, 1}, 9, heating_fitness, kept, kept_best, true);
  EXPECT_EQ(kept[1], std::log(0.1));
}

}  // namespace
}  // namespace motoflex
