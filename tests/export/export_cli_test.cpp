// `motoflex export` end to end: every format is written and read back by its parser, the MuJoCo
// check prints one JSON line, and bad input exits with code 2 and one line.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "export_test_support.hpp"
#include "motoflex/io/joint_log.hpp"
#include "motoflex/scenario/scenario.hpp"

namespace motoflex {
namespace {

using testing::run_motoflex;

// A commanded-only joint log of the bench chirp (5 s), with the sidecar's per-log parameters.
std::string write_chirp_log(const std::filesystem::path& dir) {
  ScenarioOverrides overrides;
  overrides.duration_s = 5.0;
  const Scenario s =
      load_scenario(std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/bench/chirp.yaml", overrides);
  JointLog log;
  log.joint_names = s.model->actuator_names();
  log.time_s = s.commands.times_s();
  log.commanded_rad = s.commands.angles_rad();
  log.meta.robot = s.model->name;
  log.meta.rate_hz = 100.0;
  log.meta.parameters = {{"bench.kp", 800.0}};
  const std::string path = (dir / "chirp.csv").string();
  write_joint_log(path, log);
  return path;
}

TEST(ExportCli, SaysWhenItDropsADiscoveredTorqueTerm) {
  const auto dir = testing::fresh_export_dir("cli_terms");
  const auto model = testing::load_robot("servo_pendulum");
  auto values = testing::fitted_values(*model);
  values["joint.pendulum.term_sin6"] = 0.03;  // what the loop's discovery fits for cogging
  const std::string best = testing::write_best_json(dir, *model, values);
  const std::string robot = testing::robot_dir("servo_pendulum");
  for (const std::string format : {"json", "mjcf", "sdf", "urdf"}) {
    const auto r = run_motoflex("export " + best + " --robot " + robot + " --format " + format +
                                " --out " + (dir / ("pendulum." + format)).string());
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    const bool warned =
        r.stderr_text.find("warning: joint.pendulum.term_sin6 = 0.03: a discovered torque term") !=
        std::string::npos;
    EXPECT_EQ(warned, format != "json") << format << ": " << r.stderr_text;
  }
}

TEST(ExportCli, WritesEveryFormatAndChecksMujoco) {
  const auto dir = testing::fresh_export_dir("cli");
  const auto model = testing::load_robot("servo_pendulum");
  const std::string best = testing::write_best_json(dir, *model, testing::fitted_values(*model));
  const std::string robot = testing::robot_dir("servo_pendulum");
  for (const std::string format : {"json", "urdf", "sdf", "mjcf"}) {
    const std::string out = (dir / ("pendulum." + format)).string();
    const auto r = run_motoflex("export " + best + " --robot " + robot + " --format " + format +
                                " --out " + out);
    ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
    const nlohmann::json line = nlohmann::json::parse(r.stdout_text);
    EXPECT_EQ(line["format"], format);
    EXPECT_EQ(line["servo"], "bench");
    EXPECT_TRUE(std::filesystem::file_size(out) > 100) << out;
  }

  const std::string log = write_chirp_log(dir);
  const std::string out = (dir / "checked.xml").string();
  const auto r = run_motoflex("export " + best + " --robot " + robot + " --format mjcf --out " +
                              out + " --check-mujoco " + log);
  ASSERT_EQ(r.exit_code, 0) << r.stderr_text;
  ASSERT_EQ(std::count(r.stdout_text.begin(), r.stdout_text.end(), '\n'), 1);
  const nlohmann::json line = nlohmann::json::parse(r.stdout_text);
  EXPECT_LT(line["rms_deg"].get<double>(), 1.0);
  EXPECT_LT(line["rms_deg_per_joint"]["pendulum"].get<double>(), 1.0);
  EXPECT_GT(line["mujoco_steps_per_s"].get<double>(), 0.0);
  EXPECT_GT(line["motoflex_steps_per_s"].get<double>(), 0.0);
  EXPECT_EQ(line["steps"].get<int>(), 5000);
  // The sidecar's firmware gain went into the exported (and checked) file.
  EXPECT_EQ(line["log_parameters"]["bench.kp"].get<double>(), 800.0);
  std::ifstream in(out);
  const std::string xml((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(xml.find("name=\"motoflex:bench.kp\" data=\"800\""), std::string::npos);
}

TEST(ExportCli, BadInputIsOneLineAndExitCodeTwo) {
  const auto dir = testing::fresh_export_dir("cli_bad");
  const auto nao = testing::load_robot("nao");
  const std::string nao_best = testing::write_best_json(dir, *nao, {});
  const std::string robot = testing::robot_dir("servo_pendulum");
  const std::string out = (dir / "x.out").string();
  const struct {
    std::string arguments;
    std::string expected;
  } cases[] = {
      {"export " + nao_best + " --robot " + robot + " --format urdf --out " + out,
       "provenance.robot"},
      {"export " + nao_best + " --robot " + robot + " --format obj --out " + out, "--format"},
      {"export " + nao_best + " --robot " + robot + " --format urdf --out " + out +
           " --check-mujoco x.csv",
       "--check-mujoco"},
      {"export " + nao_best + " --robot " + dir.string() + " --format urdf --out " + out,
       "robot.yaml"},
      {"export " + (dir / "missing.json").string() + " --robot " + robot + " --format json --out " +
           out,
       "cannot open"},
  };
  for (const auto& c : cases) {
    const auto r = run_motoflex(c.arguments);
    EXPECT_EQ(r.exit_code, 2) << c.arguments << "\n" << r.stderr_text;
    EXPECT_NE(r.stderr_text.find(c.expected), std::string::npos) << r.stderr_text;
    EXPECT_EQ(std::count(r.stderr_text.begin(), r.stderr_text.end(), '\n'), 1) << r.stderr_text;
  }
}

}  // namespace
}  // namespace motoflex
