// `motoflex init-robot` and `check-robot` as a user runs them: a table of assumptions and exit
// 0 for a URDF that simulates; every problem of a robot folder at once, one line each, exit 2.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli_test_support.hpp"

namespace motoflex::testing {
namespace {

const std::string kData = std::string(MOTOFLEX_SOURCE_DIR) + "/tests/data/";

std::size_t lines(const std::string& text) {
  return std::count(text.begin(), text.end(), '\n');
}

TEST(RobotCommands, InitRobotWritesAFolderThatChecksClean) {
  const auto dir = fresh_dir("cli_init_arm6");
  const CommandResult init =
      run_motoflex("init-robot " + kData + "robots/arm6/arm6.urdf --out " + dir.string());
  ASSERT_EQ(init.exit_code, 0) << init.stderr_text;
  EXPECT_EQ(init.stdout_text.rfind("assumption", 0), 0u) << init.stdout_text;  // the table
  EXPECT_NE(init.stdout_text.find("placeholder"), std::string::npos);
  EXPECT_NE(init.stdout_text.find("simulates"), std::string::npos);
  const CommandResult check = run_motoflex("check-robot " + dir.string());
  EXPECT_EQ(check.exit_code, 0) << check.stderr_text;
  EXPECT_NE(check.stdout_text.find("actuators: 7"), std::string::npos) << check.stdout_text;
  EXPECT_NE(check.stdout_text.find("completed"), std::string::npos) << check.stdout_text;
}

TEST(RobotCommands, CheckRobotListsEveryProblemAtOnce) {
  // One folder, five independent problems: an unknown robot.yaml key, an actuated joint the
  // URDF lacks, an impossible inertia, a mesh that is not there, and a missing parameter.
  const auto dir = fresh_dir("cli_check_many");
  write_text(dir / "r.urdf",
             "<robot name=\"r\">\n"
             "<link name=\"base\"><inertial><mass value=\"1\"/><inertia ixx=\"0.01\" ixy=\"0\" "
             "ixz=\"0\" iyy=\"0.01\" iyz=\"0\" izz=\"0.01\"/></inertial></link>\n"
             "<link name=\"arm\"><inertial><mass value=\"1\"/><inertia ixx=\"0.001\" ixy=\"0\" "
             "ixz=\"0\" iyy=\"0.001\" iyz=\"0\" izz=\"0.01\"/></inertial>\n"
             "<collision><geometry><mesh filename=\"package://nowhere/meshes/arm.stl\"/>"
             "</geometry></collision></link>\n"
             "<joint name=\"j\" type=\"revolute\"><parent link=\"base\"/><child link=\"arm\"/>"
             "<axis xyz=\"0 1 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" "
             "velocity=\"1\"/></joint>\n</robot>\n");
  write_text(
      dir / "robot.yaml",
      "name: r\nurdf: r.urdf\nfixed_base: true\nground: false\nservo: ideal\n"
      "colour: red\n"
      "actuated_joints:\n  - {joint: j, group: g}\n  - {joint: k, group: g}\n"
      "parameters:\n  world.erp: [0.2, 0.05, 0.9]\n  world.cfm: [1.0e-10, 1.0e-12, 1.0e-4]\n");
  const CommandResult check = run_motoflex("check-robot " + dir.string());
  EXPECT_EQ(check.exit_code, 2);
  EXPECT_EQ(lines(check.stderr_text), 5u) << check.stderr_text;
  for (const char* expected :
       {"robot.yaml:6: colour: unknown key", "robot.yaml:9: actuated_joints[1].joint: joint 'k'",
        "r.urdf:3: arm.inertial", "r.urdf:3: arm.collision[0]: mesh file", "ideal.torque_max_nm"}) {
    EXPECT_NE(check.stderr_text.find(expected), std::string::npos)
        << "expected '" << expected << "' in:\n"
        << check.stderr_text;
  }
}

TEST(RobotCommands, InitRobotRefusesAUrdfWithProblemsListingAll) {
  const auto dir = fresh_dir("cli_init_bad");
  write_text(
      dir / "bad.urdf",
      "<robot name=\"bad\">\n"
      "<link name=\"a\"><inertial><mass value=\"-1\"/><inertia ixx=\"1\" ixy=\"0\" ixz=\"0\" "
      "iyy=\"1\" iyz=\"0\" izz=\"1\"/></inertial></link>\n"
      "<link name=\"b\"><inertial><mass value=\"1\"/><inertia ixx=\"0\" ixy=\"0\" ixz=\"0\" "
      "iyy=\"0\" iyz=\"0\" izz=\"0\"/></inertial></link>\n"
      "<joint name=\"p\" type=\"planar\"><parent link=\"a\"/><child link=\"b\"/></joint>\n"
      "</robot>\n");
  const CommandResult init = run_motoflex("init-robot " + (dir / "bad.urdf").string() + " --out " +
                                          (dir / "out").string());
  EXPECT_EQ(init.exit_code, 2);
  EXPECT_EQ(lines(init.stderr_text), 3u) << init.stderr_text;
  EXPECT_NE(init.stderr_text.find("bad.urdf:2: a.inertial"), std::string::npos) << init.stderr_text;
  EXPECT_NE(init.stderr_text.find("bad.urdf:3: b.inertial: inertia is not positive definite"),
            std::string::npos);
  EXPECT_NE(init.stderr_text.find("bad.urdf:4: p.type: planar"), std::string::npos);
}

}  // namespace
}  // namespace motoflex::testing
