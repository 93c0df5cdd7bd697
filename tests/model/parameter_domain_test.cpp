// The parameter catalog's domains: each rule on an example name, and every shipped robot's
// defaults inside the domains of its parameters (a default outside would be a broken model).

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "motoflex/model/parameter_domain.hpp"
#include "motoflex/model/robot_loader.hpp"

namespace motoflex {
namespace {

TEST(ParameterDomain, RulesOfTheCatalog) {
  EXPECT_FALSE(parameter_domain("gear.A.backlash_rad").contains(-1e-9));
  EXPECT_TRUE(parameter_domain("gear.A.backlash_rad").contains(0.0));
  EXPECT_FALSE(parameter_domain("motor.R_ohm").contains(0.0));
  EXPECT_TRUE(parameter_domain("motor.R_ohm").contains(1e-9));
  EXPECT_FALSE(parameter_domain("gear.B.viscous_nm_s_per_rad").contains(-0.1));
  EXPECT_FALSE(parameter_domain("gear.B.ratio").contains(0.0));
  EXPECT_FALSE(parameter_domain("contact.mu").contains(-0.5));
  EXPECT_FALSE(parameter_domain("world.erp").contains(1.5));
  EXPECT_TRUE(parameter_domain("sensor.resolution_bits").contains(12.0));
  EXPECT_FALSE(parameter_domain("sensor.resolution_bits").contains(12.5));
  EXPECT_FALSE(parameter_domain("sensor.resolution_bits").contains(33.0));
  EXPECT_FALSE(parameter_domain("sensor.noise_rad").contains(-0.01));
  EXPECT_FALSE(parameter_domain("joint.LKneePitch.friction_model").contains(0.0));
  EXPECT_FALSE(parameter_domain("pid.kp_v_per_rad").contains(-1.0));
  EXPECT_FALSE(parameter_domain("servo.kp_divisor").contains(0.0));
  // The bench's current limit must be positive; a firmware law's 0 means no limit.
  EXPECT_FALSE(parameter_domain("motor.current_limit_a").contains(0.0));
  EXPECT_TRUE(parameter_domain("servo.arm.current_limit_a").contains(0.0));
  // Names no rule knows (an offset, a drift) take any finite number, never NaN or infinity.
  EXPECT_TRUE(parameter_domain("joint.LKneePitch.encoder_offset_rad").contains(-0.3));
  EXPECT_TRUE(parameter_domain("motor.R_drift_per_s").contains(-0.01));
  EXPECT_FALSE(parameter_domain("motor.R_drift_per_s").contains(std::nan("")));
}

TEST(ParameterDomain, IntervalsAndDescriptions) {
  const ParameterDomain backlash = parameter_domain("gear.A.backlash_rad");
  EXPECT_TRUE(backlash.contains_interval(0.0, 0.05));
  EXPECT_FALSE(backlash.contains_interval(-0.05, 0.05));
  EXPECT_EQ(backlash.describe(), "a number >= 0");
  const ParameterDomain resistance = parameter_domain("bench.R_ohm");
  EXPECT_FALSE(resistance.contains_interval(0.0, 10.0));
  EXPECT_EQ(resistance.describe(), "a number > 0");
  EXPECT_EQ(parameter_domain("sensor.resolution_bits").describe(), "an integer in [0, 32]");
  EXPECT_EQ(parameter_domain("world.erp").describe(), "a number in [0, 1]");
}

TEST(ParameterDomain, ShippedRobotDefaultsLieInTheirDomains) {
  const std::filesystem::path robots = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots";
  int checked = 0;
  for (const auto& entry : std::filesystem::directory_iterator(robots)) {
    if (!std::filesystem::exists(entry.path() / "robot.yaml")) continue;
    const RobotModel model = load_robot_model(entry.path().string(), StructureOptions{});
    const ParameterRegistry& registry = model.parameters;
    for (std::size_t i = 0; i < registry.size(); ++i) {
      EXPECT_TRUE(registry.domain(i).contains(registry.spec(i).default_value))
          << entry.path().filename() << ": " << registry.spec(i).name << " = "
          << registry.spec(i).default_value << " (" << registry.domain(i).describe() << ")";
      ++checked;
    }
  }
  EXPECT_GT(checked, 100);  // four robots of 30-100 parameters each
}

}  // namespace
}  // namespace motoflex
