// robot.yaml `joint_stops: false` (the 2011 MoToFlex robot has no LoStop/HiStop,
// motoflex_2011.md §2.10): the URDF limits stay on the actuators, for motion planners, and
// never reach the joints, which become ODE stops.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/model/robot_loader.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const fs::path kRobot = fs::path(MOTOFLEX_SOURCE_DIR) / "scenarios/robots/nao_motoflex_2011";

// A copy of the 2011 robot whose robot.yaml says `joint_stops: <value>`.
fs::path robot_with_stops(const std::string& value) {
  const fs::path dir = fresh_dir("joint_stops_" + value);
  fs::copy(kRobot / "nao_motoflex_2011.urdf", dir / "nao_motoflex_2011.urdf");
  std::ifstream in(kRobot / "robot.yaml");
  std::stringstream text;
  text << in.rdbuf();
  std::string yaml = text.str();
  const std::string key = "joint_stops: false";
  yaml.replace(yaml.find(key), key.size(), "joint_stops: " + value);
  write_text(dir / "robot.yaml", yaml);
  return dir;
}

void expect_stops(const RobotModel& model, bool stops) {
  for (const ActuatorSpec& a : model.actuators) {
    EXPECT_TRUE(std::isfinite(a.lower_rad) && std::isfinite(a.upper_rad)) << a.name;
    const JointSpec& joint = model.joints[a.joint];
    const double lower = a.axis == 1 ? joint.lower1_rad : joint.lower2_rad;
    const double upper = a.axis == 1 ? joint.upper1_rad : joint.upper2_rad;
    if (stops) {
      EXPECT_EQ(lower, a.lower_rad) << a.name;
      EXPECT_EQ(upper, a.upper_rad) << a.name;
    } else {
      EXPECT_TRUE(std::isinf(lower) && std::isinf(upper)) << a.name;
    }
  }
}

TEST(JointStops, TheOriginalsRobotHasNoneButKeepsItsLimitsForPlanners) {
  for (const int flex : {1, 2}) {
    const RobotModel model = load_robot_model(kRobot.string(), {flex, true});
    EXPECT_FALSE(model.joint_stops);
    ASSERT_EQ(model.actuators.size(), 10u);
    expect_stops(model, false);
  }
  const RobotModel with = load_robot_model(robot_with_stops("true").string(), {1, true});
  EXPECT_TRUE(with.joint_stops);
  expect_stops(with, true);
  // The default is to keep the stops: our nao's robot.yaml does not mention the key.
  const RobotModel nao =
      load_robot_model((fs::path(MOTOFLEX_SOURCE_DIR) / "scenarios/robots/nao").string(), {});
  EXPECT_TRUE(nao.joint_stops);
  expect_stops(nao, true);
}

TEST(JointStops, ANonBooleanIsAnErrorAtItsLine) {
  const fs::path dir = robot_with_stops("maybe");
  try {
    load_robot_model(dir.string(), {});
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.field(), "joint_stops") << error.what();
    EXPECT_EQ(error.line(), 13) << error.what();  // robot.yaml line of the key
  }
}

}  // namespace
}  // namespace motoflex::testing
