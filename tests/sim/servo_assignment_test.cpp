// robot.yaml `servos:` as the sim layer checks it: each joint runs its own law, an unknown law
// is reported at its `servos:` entry, and the parameters each law reads are required.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error_collector.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"
#include "robot_test_support.hpp"

namespace motoflex {
namespace {

using testing::joint;
using testing::link;

std::string two_joint_folder(const std::string& name, const std::string& servos,
                             const std::string& parameters) {
  const auto dir = testing::fresh_dir("servos_" + name);
  std::string body = link("l0", testing::box_inertial(1.0, 0.1, 0.1, 0.1));
  for (int i = 1; i <= 2; ++i) {
    const std::string n = std::to_string(i);
    body += link("l" + n, testing::box_inertial(0.5, 0.05, 0.05, 0.2, "0 0 0.1")) +
            joint("j" + n, "revolute", "l" + std::to_string(i - 1), "l" + n,
                  "<origin xyz=\"0 0 0.2\"/><axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" "
                  "effort=\"5\" velocity=\"5\"/>");
  }
  testing::write_file(dir / "c.urdf", testing::robot(name, body));
  testing::write_file(
      dir / "robot.yaml",
      "name: " + name +
          "\nurdf: c.urdf\nfixed_base: true\nground: false\nservo: ideal\n"
          "actuated_joints:\n  - {joint: j1, group: A}\n  - {joint: j2, group: B}\n" +
          servos +
          "parameters:\n  ideal.torque_max_nm: [10.0, 1.0, 100.0]\n"
          "  world.erp: [0.2, 0.05, 0.9]\n  world.cfm: [1.0e-10, 1.0e-12, 1.0e-4]\n" +
          parameters);
  return dir.string();
}

TEST(ServoAssignmentTest, EachJointRunsItsOwnLaw) {
  const RobotModel model =
      load_robot(two_joint_folder("own", "servos:\n  j2: velocity\n",
                                  "  joint.j2.gain_per_s: [4.0, 0.4, 40.0]\n"
                                  "  joint.j2.torque_max_nm: [5.0, 0.5, 50.0]\n"),
                 {});
  EXPECT_EQ(actuator_servo_name(model, "", 0), "ideal");
  EXPECT_EQ(actuator_servo_name(model, "", 1), "velocity");
  const std::vector<std::string> names = rollout_parameter_names(model, "");
  EXPECT_NE(std::find(names.begin(), names.end(), "joint.j2.gain_per_s"), names.end());
  EXPECT_EQ(std::find(names.begin(), names.end(), "joint.j1.gain_per_s"), names.end());
}

TEST(ServoAssignmentTest, UnknownLawAndMissingParametersAreReportedWhereTheyAreChosen) {
  ErrorCollector errors;
  load_robot(two_joint_folder("bad", "servos:\n  A: no_such_law\n  B: velocity\n", ""), {}, errors);
  ASSERT_EQ(errors.size(), 3u);
  EXPECT_EQ(errors.errors()[0].line(), 10);  // the `A:` entry
  EXPECT_EQ(errors.errors()[0].field(), "servos.A");
  EXPECT_NE(errors.errors()[0].message().find("unknown servo 'no_such_law'"), std::string::npos);
  // B's velocity law still gets its own check: its gain and limit are missing.
  EXPECT_NE(errors.errors()[1].message().find("joint.j2.gain_per_s"), std::string::npos);
  EXPECT_NE(errors.errors()[2].message().find("joint.j2.torque_max_nm"), std::string::npos);
}

}  // namespace
}  // namespace motoflex
