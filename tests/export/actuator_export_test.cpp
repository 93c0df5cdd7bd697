// The joint-level values every export carries, against the derivations in
// include/motoflex/export/actuator_export.hpp, computed by hand from robot.yaml defaults.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <numbers>

#include "export_test_support.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {
namespace {

ExportInput defaults(const RobotModel& model, const std::string& servo) {
  return ExportInput{model, ParameterSet(model.parameters), servo, {}, 0.001};
}

TEST(ActuatorExport, MotoflexServoLinearisedAtTheNaoDefaults) {
  const auto model = testing::load_robot("nao");
  const auto actuators = export_actuators(defaults(*model, "motoflex"));
  ASSERT_EQ(actuators.size(), 10u);
  // LHipRoll: gear A (σ = 201.3), the nominal defaults (scenarios/robots/nao/README.md).
  const ActuatorExport& roll = actuators[0];
  EXPECT_EQ(roll.joint, "LHipRoll");
  const double g = 201.3 * 0.7 * 0.0195 / 6.44;  // N·m per V at the joint
  EXPECT_NEAR(roll.kp_nm_per_rad, g * 300.0, 1e-9);
  EXPECT_NEAR(roll.kv_nm_s_per_rad, g * 0.2, 1e-12);
  EXPECT_NEAR(roll.effort_nm, g * 21.6, 1e-9);  // 9.2 N·m stall torque (README)
  EXPECT_NEAR(roll.effort_nm, 9.2, 0.05);
  EXPECT_NEAR(roll.damping_nm_s_per_rad, 1.9e-5 * 201.3 * 201.3, 1e-9);  // B·σ²
  EXPECT_NEAR(roll.friction_nm, 1.0, 1e-12);
  EXPECT_NEAR(roll.reduction, 201.3, 1e-12);
  EXPECT_NEAR(roll.armature, 1.0e-3, 1e-15);
  EXPECT_NEAR(roll.velocity_rad_s, roll.effort_nm / roll.damping_nm_s_per_rad, 1e-12);
  EXPECT_FALSE(roll.command_is_next_angle);
  // LKneePitch: gear B (σ = 130.85).
  const ActuatorExport& knee = actuators[2];
  EXPECT_EQ(knee.joint, "LKneePitch");
  EXPECT_NEAR(knee.damping_nm_s_per_rad, 1.9e-5 * 130.85 * 130.85, 1e-9);
  EXPECT_NEAR(knee.effort_nm, 130.85 * 0.7 * 0.0195 / 6.44 * 21.6, 1e-9);
  EXPECT_TRUE(knee.limited);
  EXPECT_LT(knee.lower_rad, knee.upper_rad);
}

TEST(ActuatorExport, BenchServoLinearisedAtTheXl330Defaults) {
  const auto model = testing::load_robot("servo_pendulum");
  const auto a = export_actuators(defaults(*model, "bench")).at(0);
  const double kt = 0.6, r = 2.6, u = 7.4;
  EXPECT_NEAR(a.kp_nm_per_rad, kt / r * u * 0.0028774 * 400.0, 1e-12);
  EXPECT_EQ(a.kv_nm_s_per_rad, 0.0);
  EXPECT_NEAR(a.effort_nm, kt * u / r, 1e-12);  // 1.71 N·m stall torque (README)
  EXPECT_NEAR(a.damping_nm_s_per_rad, 0.05 + kt * kt / r, 1e-12);  // viscous + back-EMF
  EXPECT_NEAR(a.friction_nm, 0.05, 1e-15);
  EXPECT_NEAR(a.armature, 0.005, 1e-15);
  EXPECT_EQ(a.reduction, 1.0);
}

TEST(ActuatorExport, BenchServoDerivativeTimeIsTheActuatorsKv) {
  // duty g·kp·(e + T_d·ė): the joint-rate part of the D term is kp_joint·T_d of damping inside
  // the force limit.
  const auto model = testing::load_robot("servo_pendulum");
  ExportInput input = defaults(*model, "bench");
  input.parameters.set("bench.derivative_s", 0.01);
  const auto a = export_actuators(input).at(0);
  EXPECT_NEAR(a.kv_nm_s_per_rad, 0.01 * a.kp_nm_per_rad, 1e-15);
  EXPECT_GT(a.kv_nm_s_per_rad, 0.0);
}

// The pendulum bench with its joint run by `law` (servo.pendulum.*) and the law's defaults.
std::shared_ptr<const RobotModel> pendulum_with(const std::string& law) {
  RobotModel model = *testing::load_robot("servo_pendulum");
  model.actuators[0].servo_scope = "pendulum";
  add_servo_law_defaults(model, law);
  return std::make_shared<const RobotModel>(std::move(model));
}

TEST(ActuatorExport, DynamixelLinearisedLikeTheBenchItReproduces) {
  // The XL330 defaults of both laws describe the same servo (kp 400, divisor 256 = BAM's
  // error gain, 885/885 duty, K_t 0.6, R 2.6, 7.4 V): the same linear PD.
  const auto model = pendulum_with("dynamixel");
  const ActuatorExport bench = export_actuators(defaults(*model, "bench")).at(0);
  ExportInput input = defaults(*model, "dynamixel");
  input.parameters.set("joint.pendulum.armature_kg_m2", 0.005);
  const ActuatorExport dynamixel = export_actuators(input).at(0);
  EXPECT_NEAR(dynamixel.kp_nm_per_rad, bench.kp_nm_per_rad, 1e-4 * bench.kp_nm_per_rad);
  EXPECT_EQ(dynamixel.kv_nm_s_per_rad, 0.0);
  EXPECT_NEAR(dynamixel.effort_nm, bench.effort_nm, 1e-12);
  EXPECT_NEAR(dynamixel.damping_nm_s_per_rad, bench.damping_nm_s_per_rad, 1e-12);
  EXPECT_EQ(dynamixel.friction_nm, bench.friction_nm);
  EXPECT_EQ(dynamixel.armature, 0.005);
  // The D register: kd/16 PWM counts per tick of change per 1 ms cycle, through g·U/885.
  input.parameters.set("servo.pendulum.kd", 32.0);
  input.parameters.set("servo.pendulum.gear_ratio", 10.0);
  input.parameters.set("servo.pendulum.Kt_nm_per_a", 0.06);
  const ActuatorExport geared = export_actuators(input).at(0);
  const double counts_to_nm = 10.0 * 0.06 / 2.6 * 7.4 / 885.0;
  EXPECT_NEAR(geared.kv_nm_s_per_rad,
              counts_to_nm * 32.0 / 16.0 * 1e-3 * 4096.0 / (2.0 * std::numbers::pi), 1e-12);
  EXPECT_NEAR(geared.damping_nm_s_per_rad, 0.05 + 0.6 * 0.6 / 2.6, 1e-12);  // N²·K_t²/R
  EXPECT_EQ(geared.reduction, 10.0);
}

TEST(ActuatorExport, PdTorqueIsItsOwnPd) {
  const auto model = pendulum_with("pd_torque");
  ExportInput input = defaults(*model, "pd_torque");
  input.parameters.set("servo.pendulum.no_load_speed_rad_s", 6.0);
  const ActuatorExport a = export_actuators(input).at(0);
  EXPECT_EQ(a.kp_nm_per_rad, 20.0);
  EXPECT_EQ(a.kv_nm_s_per_rad, 0.5);
  EXPECT_EQ(a.effort_nm, 5.0);
  EXPECT_EQ(a.velocity_rad_s, 6.0);  // the torque-speed curve's no-load speed
  EXPECT_EQ(a.damping_nm_s_per_rad, 0.05);
  EXPECT_EQ(a.friction_nm, 0.05);
}

TEST(ActuatorExport, IdealServoIsAStiffDeadbeatPd) {
  const auto model = testing::load_robot("nao");
  const ExportInput input = defaults(*model, "ideal");
  const auto actuators = export_actuators(input);
  for (std::size_t i = 0; i < actuators.size(); ++i) {
    const ActuatorExport& a = actuators[i];
    const double inertia = subtree_inertia_kg_m2(*model, i);
    EXPECT_GT(inertia, 1e-4) << a.joint;
    EXPECT_NEAR(a.kv_nm_s_per_rad * input.dt_s, 5.0 * inertia, 1e-12) << a.joint;
    EXPECT_NEAR(a.kp_nm_per_rad * input.dt_s, a.kv_nm_s_per_rad, 1e-9) << a.joint;
    EXPECT_EQ(a.effort_nm, 20.0);
    EXPECT_EQ(a.damping_nm_s_per_rad, 0.0);  // the ideal servo has no friction
    EXPECT_TRUE(a.command_is_next_angle);
  }
  // The hip carries the whole leg, the ankle roll only the foot.
  EXPECT_GT(subtree_inertia_kg_m2(*model, 0), 10.0 * subtree_inertia_kg_m2(*model, 4));
}

}  // namespace
}  // namespace motoflex
