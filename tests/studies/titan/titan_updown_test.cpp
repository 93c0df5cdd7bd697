// Seed 000 §VI, the "calibration" the paper recommends before any walking study: while the body
// rises and falls sinusoidally on its four standing feet, the joint work from bottom to top
// equals the potential-energy gain, and over a whole period it is zero. A 2 s period keeps the
// test short (the paper's study uses 4 s).

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "motoflex/studies/titan/titan_study.hpp"
#include "titan_study_test_support.hpp"

namespace motoflex {
namespace {

const TitanUpDownResult& updown() {
  static const TitanUpDownResult result = [] {
    const TitanStudyConfig& config = testing::titan_paper_config();
    TitanUpDownStudyOptions options = config.plan.updown;
    options.motion.period_s = 2.0;
    options.motion.periods = 2;
    return run_titan_updown(config.plan.setup, options);
  }();
  return result;
}

TEST(TitanUpDown, JointWorkOverTheRiseIsThePotentialEnergyGain) {
  const TitanUpDownResult& r = updown();
  ASSERT_EQ(r.end, RolloutEnd::kCompleted) << r.end_detail;
  std::cout << "rise: potential gain " << r.potential_gain_j << " J, joint work "
            << r.integrated_power_j << " J (J1-J3 " << r.integrated_power_active_j << ", eq. 7 "
            << r.integrated_power_jacobian_j << "), period integral " << r.period_integral_j
            << " J\n";
  // 20 kg above the knees rising 0.06 m: about 11 J.
  EXPECT_GT(r.potential_gain_j, 9.0);
  EXPECT_LT(r.potential_gain_j, 13.0);
  EXPECT_LT(std::abs(r.kinetic_change_j), 1e-3 * r.potential_gain_j);
  EXPECT_NEAR(r.integrated_power_j, r.potential_gain_j, 0.02 * r.potential_gain_j);
  // J1–J3 alone do nearly all of it (the ankle servos hold the soles level with ≤ 1 N·m).
  EXPECT_NEAR(r.integrated_power_active_j, r.potential_gain_j, 0.02 * r.potential_gain_j);
}

TEST(TitanUpDown, JointWorkOverAWholePeriodVanishes) {
  const TitanUpDownResult& r = updown();
  ASSERT_EQ(r.end, RolloutEnd::kCompleted) << r.end_detail;
  // Tolerance relative to the energy moved in the rise: 0.5 % of it (measured: about 0.1 %
  // with this 2 s period, 0.001 % with the study's 4 s; what is lost goes into the soft,
  // slipping contacts).
  EXPECT_LT(std::abs(r.period_integral_j), 5e-3 * r.potential_gain_j);
  EXPECT_LT(std::abs(r.period_integral_jacobian_j), 1e-2 * r.potential_gain_j);
}

TEST(TitanUpDown, EquationSevenOverestimatesTheRiseBecauseItNeglectsLegMass) {
  // Eq. 7 treats everything above the ankles as moving with the body; thighs and shanks rise
  // less than the body, so the eq. 7 work exceeds the true one (by ~15 % for this model).
  const TitanUpDownResult& r = updown();
  EXPECT_GT(r.integrated_power_jacobian_j, r.integrated_power_active_j);
  EXPECT_LT(r.integrated_power_jacobian_j, 1.3 * r.integrated_power_active_j);
}

}  // namespace
}  // namespace motoflex
