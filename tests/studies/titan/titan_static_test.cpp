// Seed 000 §III: TITAN-VIII standing in the standard posture after a 10 mm drop. Each knee
// carries the 20 kg above it (49.1 N, footnote 2) and nothing else; the J3 torque from the
// J4 force (eq. 7) settles about 5× faster than the one from joint feedback (eq. 4–5), as in the
// paper's Fig. 5. In ODE 0.16's dWorldStep the feedback itself has no latency (it is the exact
// constraint force of the step; the eq. 4 residual is 0); the slow part is physical: the shank
// also carries the ankle servo's torque to the knee, and that servo (k_d = 1/s, τ_max = 1 N·m)
// relaxes slowly, while eq. 7 ignores it.

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "motoflex/studies/titan/titan_study.hpp"
#include "titan_study_test_support.hpp"

namespace motoflex {
namespace {

const TitanStaticResult& standing() {
  static const TitanStaticResult result = [] {
    const TitanStudyConfig& config = testing::titan_paper_config();
    return run_titan_static(config.plan.setup, config.plan.stand);
  }();
  return result;
}

TEST(TitanStatic, EachKneeCarriesTheWeightAboveIt) {
  const TitanStaticResult& r = standing();
  ASSERT_EQ(r.end, RolloutEnd::kCompleted) << r.end_detail;
  EXPECT_NEAR(r.touchdown_s, 0.045, 0.002);        // 10 mm free fall: sqrt(2·0.01/9.81) = 45 ms
  EXPECT_NEAR(r.expected_knee_fz_n, 49.05, 1e-9);  // (22 − 2) kg · 9.81 / 4
  for (std::size_t l = 0; l < 4; ++l) {
    EXPECT_NEAR(r.knee_force_n[l].z(), 49.1, 0.01 * 49.1) << "leg " << l;
    EXPECT_NEAR(r.knee_force_n[l].z(), r.expected_knee_fz_n, 1e-3) << "leg " << l;
  }
}

TEST(TitanStatic, OtherKneeComponentsVanish) {
  const TitanStaticResult& r = standing();
  for (std::size_t l = 0; l < 4; ++l) {
    EXPECT_LT(std::abs(r.knee_force_n[l].x()), 0.01) << "leg " << l;
    EXPECT_LT(std::abs(r.knee_force_n[l].y()), 0.01) << "leg " << l;
    // Within 1 % of the J3 operating range (10 N·m); what is left is the ankle servo's torque,
    // still relaxing after 5 s.
    EXPECT_LT(r.knee_moment_nm[l].cwiseAbs().maxCoeff(), 0.1) << "leg " << l;
  }
}

TEST(TitanStatic, JacobianTorqueSettlesFasterThanFeedbackTorque) {
  const TitanStaticResult& r = standing();
  std::cout << "J3 settles within 0.5 N·m: feedback " << r.feedback_converge_s[0] << " s, Jacobian "
            << r.jacobian_converge_s[0] << " s after touchdown\n";
  for (std::size_t l = 0; l < 4; ++l) {
    ASSERT_TRUE(std::isfinite(r.feedback_converge_s[l]));
    ASSERT_TRUE(std::isfinite(r.jacobian_converge_s[l]));
    // Paper: feedback about 2 s, the Jacobian method almost 5 times faster.
    EXPECT_GT(r.feedback_converge_s[l], 1.0);
    EXPECT_LT(r.feedback_converge_s[l], 3.0);
    EXPECT_LT(r.jacobian_converge_s[l] * 3.0, r.feedback_converge_s[l]);
    // Both end at the static answer, no torque at the knee.
    EXPECT_LT(std::abs(r.knee_feedback_nm[l]), 0.1);
    EXPECT_LT(std::abs(r.knee_jacobian_nm[l]), 0.1);
  }
}

TEST(TitanStatic, TheGapIsTheAnkleTorqueNotAFeedbackLatency) {
  const TitanStaticResult& r = standing();
  // Newton's third law holds exactly at every step (eq. 4, first line) ...
  EXPECT_LT(r.max_third_law_residual_n, 1e-9);
  // ... and feedback − Jacobian is the ankle servo's torque up to the shank's own dynamics.
  EXPECT_LT(r.max_knee_gap_beyond_ankle_nm, 0.05);
  // Right after landing the ankle servo is at its 1 N·m limit.
  double most_ankle = 0.0;
  for (const double tau : r.ankle_feedback_series_nm[0])
    most_ankle = std::max(most_ankle, std::abs(tau));
  EXPECT_NEAR(most_ankle, 1.0, 1e-6);
}

}  // namespace
}  // namespace motoflex
