// Seed 000 §V: the crawl in postures A–D (one gait period each, to keep the test short; the
// study averages three). Posture A, the gravitationally decoupled one, needs the least averaged
// absolute power (eq. 8, Fig. 10); in B–D joints J2 and J3 of the FL leg exchange power in
// 2.4–4.8 s of its cycle: opposite signs, similar magnitude (Fig. 9).

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>

#include "motoflex/studies/titan/titan_study.hpp"
#include "titan_study_test_support.hpp"

namespace motoflex {
namespace {

const std::array<TitanCrawlResult, 4>& crawls() {
  static const std::array<TitanCrawlResult, 4> results = [] {
    const TitanStudyConfig& config = testing::titan_paper_config();
    std::array<TitanCrawlResult, 4> out;
    const std::array<TitanPosture, 4> postures = {TitanPosture::kA, TitanPosture::kB,
                                                  TitanPosture::kC, TitanPosture::kD};
#pragma omp parallel for num_threads(2) schedule(dynamic, 1)
    for (int p = 0; p < 4; ++p) {
      TitanCrawlStudyOptions options = config.plan.crawl;
      options.posture = postures[static_cast<std::size_t>(p)];
      options.periods = 1;
      out[static_cast<std::size_t>(p)] = run_titan_crawl(config.plan.setup, options);
    }
    return out;
  }();
  return results;
}

TEST(TitanCrawlPower, EveryPostureWalks) {
  for (const TitanCrawlResult& r : crawls()) {
    ASSERT_EQ(r.end, RolloutEnd::kCompleted) << to_string(r.posture) << ": " << r.end_detail;
    EXPECT_NEAR(r.advance_m, 0.24, 0.03) << to_string(r.posture);  // 0.05 m/s × 4.8 s
    std::cout << "posture " << to_string(r.posture) << ": eq. 8 " << r.jacobian.total_w << " W (J1 "
              << r.jacobian.joint_w[0] << ", J2 " << r.jacobian.joint_w[1] << ", J3 "
              << r.jacobian.joint_w[2] << "), feedback " << r.feedback.total_w
              << " W; window work J2 " << r.exchange_work_j2_j << " J, J3 " << r.exchange_work_j3_j
              << " J, corr " << r.exchange_power_correlation << "\n";
  }
}

TEST(TitanCrawlPower, PostureAHasTheLowestAveragedPower) {
  const auto& r = crawls();
  for (std::size_t p = 1; p < 4; ++p) {
    EXPECT_LT(r[0].jacobian.total_w, r[p].jacobian.total_w) << to_string(r[p].posture);
    EXPECT_LT(r[0].feedback.total_w, r[p].feedback.total_w) << to_string(r[p].posture);
  }
  // Single-digit watts, as the paper's ODE results.
  for (const TitanCrawlResult& c : r) EXPECT_LT(c.jacobian.total_w, 10.0);
}

TEST(TitanCrawlPower, JointsTwoAndThreeExchangePowerOutsidePostureA) {
  const auto& r = crawls();
  for (std::size_t p = 1; p < 4; ++p) {
    const TitanCrawlResult& c = r[p];
    const double w2 = c.exchange_work_j2_j, w3 = c.exchange_work_j3_j;
    EXPECT_LT(w2 * w3, 0.0) << to_string(c.posture) << ": opposite signs";
    EXPECT_NEAR(std::abs(w2) / std::abs(w3), 1.0, 0.25) << to_string(c.posture);
    EXPECT_LT(c.exchange_power_correlation, -0.8) << to_string(c.posture);
    // ... and far more of it than in the GDA posture, where both stay near zero.
    EXPECT_GT(c.exchange_mean_abs_power_j2_w, 2.0 * r[0].exchange_mean_abs_power_j2_w);
    EXPECT_GT(c.exchange_mean_abs_power_j3_w, 2.0 * r[0].exchange_mean_abs_power_j3_w);
  }
}

}  // namespace
}  // namespace motoflex
