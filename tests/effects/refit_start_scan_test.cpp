// The loop refit's start scan (refit_start_scan.hpp): a parameter whose neutral value does
// nothing (a current limit far above any current) is moved to where it acts; a start already
// best is kept; names not free are left alone.

#include "motoflex/effects/refit_start_scan.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "motoflex/model/parameters.hpp"

namespace motoflex {
namespace {

using Estimate = std::vector<std::pair<std::string, double>>;

class RefitStartScanTest : public ::testing::Test {
 protected:
  RefitStartScanTest() {
    registry_.add({"motor.current_limit_a", unit_from_parameter_name("motor.current_limit_a"),
                   1.0e3, 0.05, 1.0e3});
    registry_.add(
        {"joint.j.friction_nm", unit_from_parameter_name("joint.j.friction_nm"), 0.0, 0.0, 0.2});
  }
  ParameterSpace space() const {
    std::vector<FreeParameter> free;
    free.push_back({"motor.current_limit_a", {"motor.current_limit_a"}, 0.05, 1.0e3, true, 1.0e3});
    return ParameterSpace(std::move(free), ParameterSet(registry_));
  }
  ParameterRegistry registry_;
};

// A limit above 10 A never binds (fitness 1, flat: the linearised step sees no slope); below,
// the fitness is 0.5 + (ln I/1.3)² (best at 1.3 A).
double current_limit_fitness(const Estimate& e) {
  const double amps = e.front().second;
  if (amps > 10.0) return 1.0;
  const double d = std::log(amps / 1.3);
  return 0.5 + d * d;
}

TEST_F(RefitStartScanTest, AParameterThatDoesNothingAtItsStartMovesToWhereItActs) {
  Estimate estimate{{"motor.current_limit_a", 398.0}, {"joint.j.friction_nm", 0.07}};
  double best = current_limit_fitness(estimate);
  int calls = 0;
  detail::scan_effect_start(
      space(), 9,
      [&](const Estimate& e) {
        ++calls;
        return current_limit_fitness(e);
      },
      estimate, best);
  // Nine points log-spaced over [0.05, 1000] A: ratio (2e4)^(1/8) = 3.45; the nearest to 1.3 A
  // is 0.05·3.45³ = 2.05 A (fitness 0.5 + ln(2.05/1.3)² = 0.708).
  EXPECT_EQ(calls, 9);  // friction_nm is not free in this space: not scanned
  EXPECT_NEAR(estimate[0].second, 0.05 * std::pow(2.0e4, 3.0 / 8.0), 1e-9);
  EXPECT_NEAR(best, 0.5 + std::pow(std::log(estimate[0].second / 1.3), 2), 1e-12);
  EXPECT_LT(best, 0.75);
  EXPECT_EQ(estimate[1].second, 0.07);
}

TEST_F(RefitStartScanTest, AStartAlreadyBestIsKept) {
  Estimate estimate{{"motor.current_limit_a", 1.3}};
  double best = current_limit_fitness(estimate);
  detail::scan_effect_start(space(), 9, current_limit_fitness, estimate, best);
  EXPECT_EQ(estimate[0].second, 1.3);
  EXPECT_EQ(best, 0.5);
  // Fewer than three points is no scan.
  Estimate far{{"motor.current_limit_a", 398.0}};
  double far_best = 1.0;
  detail::scan_effect_start(space(), 2, current_limit_fitness, far, far_best);
  EXPECT_EQ(far[0].second, 398.0);
}

}  // namespace
}  // namespace motoflex
