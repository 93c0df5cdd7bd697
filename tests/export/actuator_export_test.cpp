// The joint-level values every export carries, against the derivations in
// include/motoflex/export/actuator_export.hpp, computed by hand from robot.yaml defaults.

#include <gtest/gtest.h>

#include "export_test_support.hpp"
#include "motoflex/export/actuator_export.hpp"

namespace motoflex {
namespace {

ExportInput defaults(const RobotModel& model, const std::string& servo) {
  return ExportInput{model, ParameterSet(model.parameters), servo, {}, 0.001};
}

TEST(ActuatorExport, MotoflexServoLinearisedAtTheNaoDefaults) {
  const auto model = testing::load_robot("nao");
  const auto actuators = export_actuators(defaults(*model, "motoflex"));
  ASSERT_EQ(actuators.size(), 10u);
  // LHipRoll: gear A (σ = 201.3), MoToFlex Normal.gnm values (scenarios/robots/nao/README.md).
  const ActuatorExport& roll = actuators[0];
  EXPECT_EQ(roll.joint, "LHipRoll");
  const double g = 201.3 * 0.7 * 0.0195 / 6.44;  // N·m per V at the joint
  EXPECT_NEAR(roll.kp_nm_per_rad, g * 319.47, 1e-9);
  EXPECT_NEAR(roll.kv_nm_s_per_rad, g * 0.1636, 1e-12);
  EXPECT_NEAR(roll.effort_nm, g * 21.6, 1e-9);  // 9.2 N·m stall torque (README)
  EXPECT_NEAR(roll.effort_nm, 9.2, 0.05);
  EXPECT_NEAR(roll.damping_nm_s_per_rad, 2.6558e-4 * 201.3 * 201.3, 1e-9);  // B·σ²
  EXPECT_NEAR(roll.friction_nm, 1.6617, 1e-12);
  EXPECT_NEAR(roll.reduction, 201.3, 1e-12);
  EXPECT_NEAR(roll.armature_kg_m2, 1.0808e-3, 1e-15);
  EXPECT_NEAR(roll.velocity_rad_s, roll.effort_nm / roll.damping_nm_s_per_rad, 1e-12);
  EXPECT_FALSE(roll.command_is_next_angle);
  // LKneePitch: gear B (σ = 130.85).
  const ActuatorExport& knee = actuators[2];
  EXPECT_EQ(knee.joint, "LKneePitch");
  EXPECT_NEAR(knee.damping_nm_s_per_rad, 2.9675e-4 * 130.85 * 130.85, 1e-9);
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
  EXPECT_NEAR(a.armature_kg_m2, 0.005, 1e-15);
  EXPECT_EQ(a.reduction, 1.0);
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
