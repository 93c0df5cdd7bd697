// NaoWalkParams::zmp_transfer_smoothing: the reference ZMP takes the same path from foot to foot
// in each double support, only the timing changes, from constant speed (0, the default, the
// walks of reference_data/) to a smoothstep that starts and stops at rest (1).

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "motoflex/model/robot_loader.hpp"
#include "motoflex/motion/nao_walk.hpp"

namespace motoflex {
namespace {

const RobotModel& nao() {
  static const RobotModel model =
      load_robot_model(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/nao", {});
  return model;
}

NaoWalkPlan plan(double smoothing) {
  NaoWalkParams p;
  p.speed_mm_s = 50.0;
  p.step_duration_s = 2.0;  // steps of 1 s, double support 0.2 s = 20 frames at 100 Hz
  p.duration_s = 8.0;
  p.zmp_transfer_smoothing = smoothing;
  return plan_nao_walk(nao(), p);
}

// Lateral reference ZMP speed (m/s) over frame f → f + 1.
double zmp_speed_y(const NaoWalkPlan& plan, std::size_t f) {
  return (plan.samples[f + 1].zmp_ref_m.y() - plan.samples[f].zmp_ref_m.y()) * 100.0;
}

TEST(ZmpTransfer, SmoothingKeepsThePathAndStartsAndStopsTheTransferAtRest) {
  const NaoWalkPlan linear = plan(0.0);
  const NaoWalkPlan smooth = plan(1.0);
  ASSERT_EQ(linear.samples.size(), smooth.samples.size());
  // The second step's double support: t = 2.0 … 2.2 s, frames 200 … 220.
  const std::size_t begin = 200, end = 220, middle = 210;
  // Same end points and, smoothstep(1/2) = 1/2, the same midpoint.
  for (const std::size_t f : {begin, middle, end}) {
    EXPECT_NEAR((linear.samples[f].zmp_ref_m - smooth.samples[f].zmp_ref_m).norm(), 0.0, 1e-12)
        << f;
  }
  // Linear: one speed throughout (0.06 m in 0.2 s: 0.3 m/s); smooth: near rest at both ends
  // (measured over the first and last frame: 2.3 % of that), 1.875× the mean speed in the middle
  // (the smoothstep's peak slope 15/8).
  const double mean = zmp_speed_y(linear, middle);
  EXPECT_NEAR(std::abs(mean), 0.3, 1e-9);
  EXPECT_NEAR(zmp_speed_y(linear, begin), mean, 1e-9);
  EXPECT_NEAR(zmp_speed_y(linear, end - 1), mean, 1e-9);
  EXPECT_LT(std::abs(zmp_speed_y(smooth, begin)), 0.05 * std::abs(mean));
  EXPECT_LT(std::abs(zmp_speed_y(smooth, end - 1)), 0.05 * std::abs(mean));
  EXPECT_NEAR(zmp_speed_y(smooth, middle) / mean, 1.875, 0.02);
  // Single support: both hold the ZMP on the support foot alike.
  EXPECT_NEAR((linear.samples[250].zmp_ref_m - smooth.samples[250].zmp_ref_m).norm(), 0.0, 1e-12);
}

TEST(ZmpTransfer, ZeroIsTheDefaultPlanBitForBitAndOutOfRangeIsRefused) {
  NaoWalkParams defaults;
  defaults.speed_mm_s = 50.0;
  defaults.step_duration_s = 2.0;
  defaults.duration_s = 8.0;
  EXPECT_EQ(plan_nao_walk(nao(), defaults).commands.angles_rad(), plan(0.0).commands.angles_rad());
  NaoWalkParams bad = defaults;
  bad.zmp_transfer_smoothing = 1.5;
  EXPECT_NE(bad.validate().find("zmp_transfer_smoothing"), std::string::npos) << bad.validate();
  // Toe-off waits for the ZMP to pass the toe edge, later on a smoothstep: the 150 mm/s long-step
  // walk still plans; 200 mm/s at 2 s reaches only 191 mm/s (measured with motoflex simulate).
  NaoWalkParams toe_off;
  toe_off.speed_mm_s = 150.0;
  toe_off.step_duration_s = 2.0;
  toe_off.toe_off_rad = 0.8;
  toe_off.heel_strike_rad = 0.6;
  toe_off.double_support_ratio = 0.4;
  toe_off.zmp_transfer_smoothing = 1.0;
  EXPECT_NO_THROW(plan_nao_walk(nao(), toe_off));
  toe_off.speed_mm_s = 200.0;
  EXPECT_THROW(plan_nao_walk(nao(), toe_off), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
