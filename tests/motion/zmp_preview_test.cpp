#include "motoflex/motion/zmp_preview.hpp"

#include <gtest/gtest.h>

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <cmath>
#include <numeric>

namespace motoflex {
namespace {

TEST(DiscreteRiccati, SolvesTheEquationAndMatchesTheRecursion) {
  Eigen::MatrixXd A(2, 2), B(2, 1), Q(2, 2), R(1, 1);
  A << 1.0, 0.1, 0.0, 1.0;  // double integrator
  B << 0.005, 0.1;
  Q << 1.0, 0.0, 0.0, 0.1;
  R << 0.01;
  const Eigen::MatrixXd P = solve_discrete_riccati(A, B, Q, R);
  // Plain Riccati recursion from P = Q converges to the same stabilising solution.
  Eigen::MatrixXd Pk = Q;
  for (int k = 0; k < 5000; ++k) {
    const Eigen::MatrixXd S = R + B.transpose() * Pk * B;
    Pk = Q + A.transpose() * Pk * A -
         A.transpose() * Pk * B * S.ldlt().solve(B.transpose() * Pk * A);
  }
  EXPECT_LT((P - Pk).norm(), 1e-9 * P.norm());
  EXPECT_LT((P - P.transpose()).norm(), 1e-12);
  // The closed loop is stable.
  const Eigen::MatrixXd K = (R + B.transpose() * P * B).ldlt().solve(B.transpose() * P * A);
  const Eigen::VectorXcd poles = (A - B * K).eigenvalues();
  for (Eigen::Index i = 0; i < poles.size(); ++i) EXPECT_LT(std::abs(poles(i)), 1.0);
}

TEST(DiscreteRiccati, RejectsInconsistentSizes) {
  EXPECT_THROW(
      solve_discrete_riccati(Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Ones(3, 1),
                             Eigen::MatrixXd::Identity(2, 2), Eigen::MatrixXd::Identity(1, 1)),
      std::invalid_argument);
}

TEST(ZmpPreview, GainsHaveKajitasShape) {
  const ZmpPreviewController controller({});
  const auto& gp = controller.preview_gains();
  ASSERT_EQ(gp.size(), 160u);  // 1.6 s at 10 ms
  EXPECT_GT(controller.integral_gain(), 0.0);
  EXPECT_DOUBLE_EQ(gp[0], -controller.integral_gain());
  // The preview gains decay: a reference 1.6 s ahead hardly matters any more.
  EXPECT_LT(std::abs(gp.back()), 1e-3 * std::abs(gp[0]));
  // At rest on a constant reference the input is zero: G_x·(r, 0, 0) + Σ G_p·r = 0.
  const double sum = std::accumulate(gp.begin(), gp.end(), 0.0);
  EXPECT_NEAR(controller.state_gain()(0) + sum, 0.0, 1e-3 * std::abs(controller.state_gain()(0)));
}

// A reference that steps 0.1 m sideways and back, like a weight shift: the cart-table ZMP of the
// computed CoM follows it closely, the CoM starts moving before the step (preview) and ends at
// rest on the final reference.
TEST(ZmpPreview, TracksAStepReference) {
  ZmpPreviewOptions options;
  options.com_height_m = 0.24;
  const ZmpPreviewController controller(options);
  std::vector<double> ref(600, 0.0);
  for (std::size_t k = 200; k < 350; ++k) ref[k] = 0.1;
  const auto track = controller.track(ref);
  for (std::size_t k = 0; k < ref.size(); ++k) {
    // The table ZMP is c − (z_c/g)·c̈.
    EXPECT_NEAR(track.zmp_m[k], track.com_m[k] - 0.24 / 9.81 * track.accel_m_s2[k], 1e-15);
    // A jump cannot be followed exactly, but half a second after it the ZMP is on the reference.
    const bool settled = (k > 50 && k < 150) || (k > 250 && k < 300) || k > 400;
    if (settled) {
      EXPECT_NEAR(track.zmp_m[k], ref[k], 5e-4) << "k = " << k;
    }
  }
  EXPECT_GT(track.com_m[195], 0.001);  // anticipation
  EXPECT_NEAR(track.com_m.back(), 0.0, 1e-4);
  EXPECT_NEAR(track.velocity_m_s.back(), 0.0, 1e-4);
}

TEST(ZmpPreview, RejectsBadOptions) {
  ZmpPreviewOptions options;
  options.com_height_m = 0.0;
  EXPECT_THROW(ZmpPreviewController{options}, std::invalid_argument);
  options = {};
  options.jerk_weight = 0.0;
  EXPECT_THROW(ZmpPreviewController{options}, std::invalid_argument);
  options = {};
  options.preview_s = 0.001;
  EXPECT_THROW(ZmpPreviewController{options}, std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
