// robot.yaml's newer keys: `servos:` gives joints and groups their own law and parameter
// scope, `joint_limits:` and `joint_stops:` replace or drop the URDF's stops, and a folder
// with several problems reports them all.

#include <gtest/gtest.h>

#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "robot_test_support.hpp"

namespace motoflex {
namespace {

using testing::joint;
using testing::link;

// A chain of three hinges j1..j3 on a welded base.
std::string chain_folder(const std::string& name, const std::string& yaml_extra) {
  const auto dir = testing::fresh_dir("yaml_" + name);
  std::string body = link("l0", testing::box_inertial(1.0, 0.1, 0.1, 0.1));
  for (int i = 1; i <= 3; ++i) {
    const std::string n = std::to_string(i);
    body += link("l" + n, testing::box_inertial(0.5, 0.05, 0.05, 0.2, "0 0 0.1")) +
            joint("j" + n, "revolute", "l" + std::to_string(i - 1), "l" + n,
                  "<origin xyz=\"0 0 0.2\"/><axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" "
                  "effort=\"5\" velocity=\"5\"/>");
  }
  testing::write_file(dir / "c.urdf", testing::robot(name, body));
  testing::write_file(dir / "robot.yaml",
                      "name: " + name +
                          "\nurdf: c.urdf\nfixed_base: true\nservo: ideal\n"
                          "actuated_joints:\n  - {joint: j1, group: A}\n  - {joint: j2, group: A}\n"
                          "  - {joint: j3, group: B}\n" +
                          yaml_extra + "parameters: {}\n");
  return dir.string();
}

TEST(RobotYamlSectionsTest, ServosGiveJointsAndGroupsTheirLawAndScope) {
  const RobotModel model =
      load_robot_model(chain_folder("servos", "servos:\n  A: velocity\n  j2: bench\n"), {});
  EXPECT_EQ(model.actuators[0].servo, "velocity");  // group A
  EXPECT_EQ(model.actuators[0].servo_scope, "A");
  EXPECT_EQ(model.actuators[1].servo, "bench");  // its own entry wins over its group's
  EXPECT_EQ(model.actuators[1].servo_scope, "j2");
  EXPECT_EQ(model.actuators[2].servo, "");  // the robot's servo
  EXPECT_EQ(model.actuators[2].servo_scope, "B");
  EXPECT_EQ(model.source.servos_lines.at("j2"), 11);
}

TEST(RobotYamlSectionsTest, JointLimitsAndJointStopsReplaceTheUrdfs) {
  const RobotModel limited =
      load_robot_model(chain_folder("limits", "joint_limits:\n  j2: [-0.5, 0.25]\n"), {});
  EXPECT_EQ(limited.joints[1].upper1_rad, 0.25);
  EXPECT_EQ(limited.actuators[1].lower_rad, -0.5);
  EXPECT_EQ(limited.joints[0].upper1_rad, 1.0);
  const RobotModel free = load_robot_model(chain_folder("no_stops", "joint_stops: false\n"), {});
  for (const JointSpec& j : free.joints) EXPECT_FALSE(std::isfinite(j.upper1_rad));
  EXPECT_EQ(free.actuators[0].upper_rad, 1.0);  // the range stays known to motions
}

TEST(RobotYamlSectionsTest, EveryProblemOfTheFolderIsReported) {
  ErrorCollector errors;
  const auto model =
      load_robot_model(chain_folder("many",
                                    "servos:\n  C: velocity\nfeet: [nowhere]\njoint_limits:\n"
                                    "  j9: [0, 1]\nheld_joints: {j3: 0.0}\nbogus: 1\n"),
                       {}, errors);
  ASSERT_TRUE(model.has_value());  // built from what could be read
  std::string all;
  for (const InputError& e : errors.errors()) all += std::string(e.what()) + "\n";
  EXPECT_EQ(errors.size(), 5u) << all;
  for (const char* expected : {"bogus", "servos.C", "feet", "j9", "both actuated and held"}) {
    EXPECT_NE(all.find(expected), std::string::npos) << expected << " in\n" << all;
  }
}

}  // namespace
}  // namespace motoflex
