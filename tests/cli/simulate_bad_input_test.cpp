// `motoflex simulate` on bad input: one line naming file, line and field; exit code 2; no
// output file left behind.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "cli_test_support.hpp"
#include "motoflex/io/joint_log.hpp"

namespace motoflex::testing {
namespace {

const std::string kRobot = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/nao";

std::string scenario_text(const std::string& physics_extra, const std::string& motion) {
  return "robot: " + kRobot + "\nservo: ideal\nphysics:\n  dt_s: 0.001\n" + physics_extra +
         "motion:\n" + motion;
}

struct BadCase {
  std::string name;
  std::string scenario;
  std::string expect_in_message;  // field name (and line) that must be reported
};

void expect_clean_failure(const std::filesystem::path& dir, const CommandResult& result,
                          const std::string& expected) {
  EXPECT_EQ(result.exit_code, 2) << result.stderr_text;
  EXPECT_EQ(std::count(result.stderr_text.begin(), result.stderr_text.end(), '\n'), 1)
      << result.stderr_text;
  EXPECT_NE(result.stderr_text.find(expected), std::string::npos)
      << "expected '" << expected << "' in: " << result.stderr_text;
  EXPECT_FALSE(std::filesystem::exists(dir / "out.csv"));
  EXPECT_FALSE(std::filesystem::exists(dir / "out.yaml"));
}

TEST(SimulateBadInput, ScenarioErrorsNameFileLineAndField) {
  const std::string stand = "  stand: {duration_s: 1}\n";
  const std::vector<BadCase> cases = {
      {"unknown key", scenario_text("  dt_ss: 0.001\n", stand), "scenario.yaml:5: physics.dt_ss"},
      {"ill-typed", scenario_text("  settle_s: abc\n", stand), "scenario.yaml:5: physics.settle_s"},
      {"missing motion", "robot: " + kRobot + "\n", "scenario.yaml:1"},
      {"bad solver", scenario_text("  solver: fast\n", stand), "physics.solver"},
      {"unknown parameter", scenario_text("", stand) + "parameters:\n  motor.R_ohms: 3\n",
       "parameters.motor.R_ohms"},
      {"bad robot", "robot: /nonexistent\nmotion:\n" + stand, "scenario.yaml:1: robot"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const auto dir = fresh_dir("sim_bad_scenario");
    write_text(dir / "scenario.yaml", c.scenario);
    const auto result = run_motoflex("simulate " + (dir / "scenario.yaml").string() + " --out " +
                                     (dir / "out.csv").string());
    expect_clean_failure(dir, result, c.expect_in_message);
  }
}

TEST(SimulateBadInput, LogErrorsNameFileLineAndColumn) {
  const std::string header =
      "time_s,LHipRoll.cmd,LHipPitch.cmd,LKneePitch.cmd,LAnklePitch.cmd,LAnkleRoll.cmd,"
      "RHipRoll.cmd,RHipPitch.cmd,RKneePitch.cmd,RAnklePitch.cmd,RAnkleRoll.cmd\n";
  const std::string row0 = "0,0,0,0,0,0,0,0,0,0,0\n";
  const std::string row1 = "0.01,0,0,0,0,0,0,0,0,0,0\n";
  const std::vector<std::pair<std::string, std::string>> logs = {
      {header + row0 + "0.01,0,0,0,0,0,0,0,0,0,nan\n", "log.csv:3"},  // NaN
      {header + row1 + row0, "log.csv:3"},                            // time goes back
      {"time_s,LHipRoll.cmd\n0,0\n0.01,0\n", "LHipPitch"},            // missing column
      {header + row0 + "0.01,0,0,x,0,0,0,0,0,0,0\n", "log.csv:3: LKneePitch.cmd"},  // not a number
  };
  for (const auto& [log, expected] : logs) {
    SCOPED_TRACE(expected);
    const auto dir = fresh_dir("sim_bad_log");
    write_text(dir / "scenario.yaml", scenario_text("", "  stand: {duration_s: 1}\n"));
    write_text(dir / "log.csv", log);
    const auto result =
        run_motoflex("simulate " + (dir / "scenario.yaml").string() + " --motion " +
                     (dir / "log.csv").string() + " --out " + (dir / "out.csv").string());
    expect_clean_failure(dir, result, expected);
  }
}

TEST(SimulateBadInput, UrdfErrorNamesTheFile) {
  const auto dir = fresh_dir("sim_bad_urdf");
  std::filesystem::create_directories(dir / "robot");
  write_text(dir / "robot" / "robot.urdf",
             "<robot name=\"r\">\n  <link name=\"a\"/>\n  <joint name=\"j\" type=\"revolute\">\n"
             "    <parent link=\"a\"/>\n    <child link=\"missing\"/>\n  </joint>\n</robot>\n");
  write_text(dir / "robot" / "robot.yaml",
             "name: r\nurdf: robot.urdf\nroot_link: a\nservo: ideal\n"
             "actuated_joints:\n  - {joint: j, group: A}\nparameters: {}\n");
  write_text(dir / "scenario.yaml",
             "robot: " + (dir / "robot").string() + "\nmotion:\n  stand: {duration_s: 1}\n");
  const auto result = run_motoflex("simulate " + (dir / "scenario.yaml").string() + " --out " +
                                   (dir / "out.csv").string());
  expect_clean_failure(dir, result, "robot.urdf");
}

TEST(SimulateGoodInput, WritesLogAndSummary) {
  const auto dir = fresh_dir("sim_good");
  write_text(dir / "scenario.yaml", scenario_text("", "  stand: {duration_s: 0.5}\n"));
  const auto result = run_motoflex("simulate " + (dir / "scenario.yaml").string() + " --out " +
                                   (dir / "out.csv").string());
  ASSERT_EQ(result.exit_code, 0) << result.stderr_text;
  EXPECT_NE(result.stdout_text.find("\"end\":\"completed\""), std::string::npos);
  // The log holds the whole motion at the scenario's 100 Hz, and the ideal servos hold the
  // stand pose: every simulated encoder within 1e-7 rad of its command (measured: 8.8e-9 rad).
  JointLogRequirements requirements;
  requirements.need_commanded = true;
  requirements.need_measured = true;
  const JointLog log = read_joint_log((dir / "out.csv").string(), requirements);
  ASSERT_EQ(log.frames(), 51u);
  EXPECT_NEAR(log.time_s.back() - log.time_s.front(), 0.5, 1e-9);
  EXPECT_EQ(log.joints(), 10u);
  double worst_rad = 0.0;
  for (std::size_t f = 0; f < log.frames(); ++f) {
    for (std::size_t j = 0; j < log.joints(); ++j) {
      worst_rad = std::max(worst_rad, std::abs(log.measured(f, j) - log.commanded(f, j)));
    }
  }
  EXPECT_LT(worst_rad, 1e-7);
  EXPECT_EQ(log.meta.robot, "nao");
  EXPECT_NEAR(log.meta.rate_hz, 100.0, 1e-9);
}

}  // namespace
}  // namespace motoflex::testing
