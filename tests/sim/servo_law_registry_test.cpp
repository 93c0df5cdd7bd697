// The registry's view of the new laws: their own parameters have defaults for exactly the
// servo.<scope>.* names they read, a robot that lacks them hears of all of them at once, and the
// effect library's friction and armature effects apply exactly under the laws that read them.

#include <gtest/gtest.h>

#include <set>
#include <string>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/effect_library.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "motoflex/sim/effect_hooks.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "one_joint_robot.hpp"

namespace motoflex {
namespace {

const testing::OneJointRobot kPendulum{};

TEST(ServoLawRegistryTest, DefaultsCoverExactlyTheLawsOwnNames) {
  for (const char* law : {"pd_torque", "dynamixel", "feetech"}) {
    const RobotModel model =
        testing::make_one_joint_robot(std::string("registry_") + law, kPendulum, law);
    const ServoLawInfo& info = servo_law(law);
    ASSERT_NE(info.default_parameters, nullptr) << law;
    std::set<std::string> own;
    for (const std::string& name : info.parameter_names(model, 0)) {
      ASSERT_TRUE(model.parameters.contains(name)) << law << ": " << name;
      if (name.rfind("servo.hinge.", 0) == 0) own.insert(name);
    }
    std::set<std::string> defaulted;
    for (const ParameterSpec& spec : info.default_parameters(model, 0)) {
      EXPECT_LE(spec.lower, spec.default_value) << spec.name;
      EXPECT_LE(spec.default_value, spec.upper) << spec.name;
      defaulted.insert(spec.name);
    }
    EXPECT_EQ(own, defaulted) << law;
    EXPECT_EQ(own.size(), std::string(law) == "pd_torque" ? 4u : 17u) << law;
  }
}

TEST(ServoLawRegistryTest, ARobotWithoutTheLawsParametersHearsOfAllAtOnce) {
  // The one-joint robot as loaded, before add_servo_law_defaults: servo: dynamixel.
  RobotModel model = testing::make_one_joint_robot("registry_missing", kPendulum, "ideal");
  model.default_servo = "dynamixel";
  try {
    check_robot_parameters(model);
    FAIL() << "expected the missing servo.hinge.* names";
  } catch (const InputErrors& errors) {
    EXPECT_EQ(errors.errors().size(), 17u);
    for (const InputError& e : errors.errors()) {
      EXPECT_NE(std::string(e.what()).find("'servo.hinge."), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("servo 'dynamixel'"), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(add_servo_law_defaults(model).size(), 17u);
  EXPECT_NO_THROW(check_robot_parameters(model));
}

TEST(ServoLawRegistryTest, FrictionAndArmatureEffectsApplyWhereTheLawsReadThem) {
  const RobotModel model = [] {
    RobotModel m = testing::make_one_joint_robot("registry_effects", kPendulum, "pd_torque");
    for (const char* law : {"dynamixel", "feetech"}) add_servo_law_defaults(m, law);
    return m;
  }();
  const auto applies = [&](const char* effect, const char* law) {
    return effect_applies(find_effect(effect), model, law);
  };
  for (const char* law : {"velocity", "pd_torque", "dynamixel", "feetech", "bench", "motoflex"}) {
    EXPECT_TRUE(applies("coulomb_friction", law)) << law;
    EXPECT_TRUE(applies("viscous_friction", law)) << law;
    EXPECT_TRUE(applies("stribeck", law)) << law;
    // The armature is the arm's point mass under bench (bench.armature_kg_m2).
    EXPECT_EQ(applies("armature", law), std::string(law) != "bench") << law;
  }
  EXPECT_FALSE(applies("coulomb_friction", "ideal"));
  EXPECT_TRUE(applies("armature", "ideal"));
  for (const char* effect :
       {"directional_load_friction", "load_stribeck_friction", "quadratic_load_friction"}) {
    // bench reads BAM's whole family (M1-M6) like the firmware laws.
    for (const char* law : {"pd_torque", "dynamixel", "feetech", "bench"}) {
      EXPECT_TRUE(applies(effect, law)) << effect << " " << law;
    }
    for (const char* law : {"velocity", "motoflex", "ideal"}) {
      EXPECT_FALSE(applies(effect, law)) << effect << " " << law;
    }
  }
  // The velocity law's torque is its row's force, unknown before the step: no load friction.
  EXPECT_FALSE(applies("load_friction", "velocity"));
  EXPECT_TRUE(applies("load_friction", "dynamixel"));
  // The driver's current limit: the bench's voltage servo reads motor.current_limit_a (the
  // firmware laws have their own servo.<scope>.current_limit_a, set from the servo's registers).
  EXPECT_TRUE(applies("current_limit", "bench"));
  for (const char* law : {"velocity", "pd_torque", "motoflex", "ideal"}) {
    EXPECT_FALSE(applies("current_limit", law)) << law;
  }
  // The motor's torque saturation: the H-bridge laws (bench, dynamixel, feetech).
  for (const char* law : {"bench", "dynamixel", "feetech"}) {
    EXPECT_TRUE(applies("torque_saturation", law)) << law;
  }
  for (const char* law : {"velocity", "pd_torque", "motoflex", "ideal"}) {
    EXPECT_FALSE(applies("torque_saturation", law)) << law;
  }
  // The logged housing temperature: the bench law reads each log's motor.housing_temperature_c.
  EXPECT_TRUE(applies("housing_temperature", "bench"));
  for (const char* law : {"dynamixel", "feetech", "velocity", "pd_torque", "motoflex", "ideal"}) {
    EXPECT_FALSE(applies("housing_temperature", law)) << law;
  }
  // The bench firmware's D (the firmware laws have their own kd; motoflex's PID its kd).
  EXPECT_TRUE(applies("servo_derivative", "bench"));
  for (const char* law : {"dynamixel", "feetech", "velocity", "pd_torque", "motoflex", "ideal"}) {
    EXPECT_FALSE(applies("servo_derivative", law)) << law;
  }
}

}  // namespace
}  // namespace motoflex
