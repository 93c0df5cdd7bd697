// The MJCF export simulated by MuJoCo 2.2.2 against motoflex's own ODE rollout on the same
// 5 s commanded log, 1 ms steps in both: joint angles agree within 1° RMS for the pendulum
// bench, for the Nao with ideal servos held in the air, and for the held Nao with the full
// MoToFlex servo.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "export_test_support.hpp"
#include "motoflex/export/mujoco_check.hpp"
#include "motoflex/scenario/scenario.hpp"

namespace motoflex {
namespace {

CommandTrajectory five_seconds_of(const std::string& scenario) {
  ScenarioOverrides overrides;
  overrides.duration_s = 5.0;
  return load_scenario(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/" + scenario, overrides)
      .commands;
}

void print(const char* what, const MujocoComparison& c) {
  std::printf(
      "%s: RMS %.4f deg (max %.4f deg) over %zu steps; MuJoCo %.0f steps/s, motoflex %.0f "
      "steps/s\n",
      what, c.rms_deg, c.max_abs_deg, c.steps, c.mujoco_steps_per_s, c.motoflex_steps_per_s);
  std::printf("  %zu geoms in the exported model\n", c.geoms);
  for (std::size_t j = 0; j < c.joints.size(); ++j) {
    std::printf("  %-12s %.4f deg\n", c.joints[j].c_str(), c.rms_deg_per_joint[j]);
  }
}

TEST(MujocoCheck, PendulumBenchServoAgreesWithinOneDegree) {
  const auto f = testing::fitted_fixture("servo_pendulum", "bench");
  const CommandTrajectory commands = five_seconds_of("bench/chirp.yaml");
  const MujocoComparison c = compare_with_mujoco(*f.input, commands, MujocoCheckOptions{});
  print("pendulum, bench servo", c);
  EXPECT_EQ(c.steps, 5000u);
  EXPECT_EQ(c.motoflex_end, "completed");
  EXPECT_LT(c.rms_deg, 0.35);  // measured 0.115 deg (max 0.40)
  EXPECT_GT(c.rms_deg, 0.0);   // two different engines: never bit-identical
  // The chirp swings the arm by up to ~1 rad; the agreement is not a trivially small motion.
  double peak = 0.0;
  for (std::size_t k = 0; k < commands.frames(); ++k) {
    peak = std::max(peak, std::abs(commands.angle_rad(k, 0)));
  }
  EXPECT_GT(peak, 0.5);
}

TEST(MujocoCheck, HeldNaoWithIdealServosAgreesWithinOneDegree) {
  const auto f = testing::fitted_fixture("nao", "ideal");
  MujocoCheckOptions options;
  options.hold_torso = true;
  options.settle_s = 0.5;
  const MujocoComparison c =
      compare_with_mujoco(*f.input, five_seconds_of("nao/excitation_held.yaml"), options);
  print("held Nao, ideal servos", c);
  EXPECT_EQ(c.steps, 5000u);
  EXPECT_EQ(c.geoms, 29u);  // the Nao's 14 collision boxes, 14 visual boxes, the floor
  EXPECT_EQ(c.visual_geoms, 14u);
  EXPECT_LT(c.rms_deg, 0.002);  // measured 0.0005 deg (max 0.0084)
  for (std::size_t j = 0; j < c.joints.size(); ++j) {
    EXPECT_LT(c.rms_deg_per_joint[j], 0.005) << c.joints[j];
  }
}

TEST(MujocoCheck, HeldNaoWithTheMotoflexServo) {
  MujocoCheckOptions options;
  options.hold_torso = true;
  options.settle_s = 0.5;
  const CommandTrajectory commands = five_seconds_of("nao/excitation_held.yaml");
  // The reflected back-EMF B·σ² is a true damper in both engines (motoflex: an implicit motor
  // row with CFM = 1/(B·σ²); MuJoCo: joint damping), so what the export drops (backlash, gear
  // spring and mass, PID integral, inductance) costs well under a degree, at the MoToFlex values
  // and with B at its lower bound alike.
  const auto defaults = testing::fitted_fixture("nao", "motoflex");
  const MujocoComparison fitted = compare_with_mujoco(*defaults.input, commands, options);
  print("held Nao, motoflex servo, MoToFlex values", fitted);
  EXPECT_LT(fitted.rms_deg, 0.2);  // measured 0.060 deg (max 0.21)
  for (std::size_t j = 0; j < fitted.joints.size(); ++j) {
    EXPECT_LT(fitted.rms_deg_per_joint[j], 0.3) << fitted.joints[j];
  }
  auto f = testing::fitted_fixture("nao", "motoflex");
  f.input->parameters.set("gear.A.motor_viscous_nm_s_per_rad", 2.6558e-5);
  f.input->parameters.set("gear.B.motor_viscous_nm_s_per_rad", 2.9675e-5);
  const MujocoComparison low_b = compare_with_mujoco(*f.input, commands, options);
  print("held Nao, motoflex servo, B at its lower bound", low_b);
  EXPECT_LT(low_b.rms_deg, 0.2);  // measured 0.069 deg (max 0.37)
}

}  // namespace
}  // namespace motoflex
