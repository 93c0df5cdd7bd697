// The commands issue 17 adds or extends, end to end: import-motoflex (the 2011 program's command
// files), simulate on a truth file and on a command file, experiment seed001. Bad input: one
// line `motoflex: <file>:<line>: <field>: <message>`, exit code 2.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_support.hpp"
#include "motoflex/io/joint_log.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const std::string kSource = MOTOFLEX_SOURCE_DIR;

// Four rows of a crouch in the original's format (written here; LHipRoll/LAnkleRoll mirrored).
const char* kCommands =
    "LHipRoll;LHipPitch;LKneePitch;LAnklePitch;LAnkleRoll;RHipRoll;RHipPitch;RKneePitch;"
    "RAnklePitch;RAnkleRoll\n"
    "0;0;0;0;0;0;0;0;0;0\n"
    "0.01;-0.1;0.2;-0.1;-0.01;0.01;-0.1;0.2;-0.1;-0.01\n"
    "0.02;-0.2;0.4;-0.2;-0.02;0.02;-0.2;0.4;-0.2;-0.02\n"
    "0.03;-0.3;0.6;-0.3;-0.03;0.03;-0.3;0.6;-0.3;-0.03\n";

void expect_one_line_error(const CommandResult& result, const std::string& expected) {
  EXPECT_EQ(result.exit_code, 2) << result.stderr_text;
  EXPECT_EQ(std::count(result.stderr_text.begin(), result.stderr_text.end(), '\n'), 1)
      << result.stderr_text;
  EXPECT_EQ(result.stderr_text.rfind("motoflex: ", 0), 0u) << result.stderr_text;
  EXPECT_NE(result.stderr_text.find(expected), std::string::npos) << result.stderr_text;
}

TEST(ImportMotoflex, WritesALogWithSidecarAndRefusesBadInput) {
  const fs::path dir = fresh_dir("import_motoflex");
  write_text(dir / "walk.csv", kCommands);
  const auto result = run_motoflex("import-motoflex " + (dir / "walk.csv").string() + " --out " +
                                   (dir / "out" / "log.csv").string());
  ASSERT_EQ(result.exit_code, 0) << result.stderr_text;
  std::ifstream csv(dir / "out" / "log.csv");
  std::string header, first, second;
  std::getline(csv, header);
  std::getline(csv, first);
  std::getline(csv, second);
  EXPECT_EQ(header.rfind("time_s,LHipRoll.cmd,LHipPitch.cmd", 0), 0u) << header;
  EXPECT_EQ(second.rfind("0.02,-0.01,-0.1,0.2", 0), 0u) << second;  // LHipRoll negated
  std::ifstream sidecar(dir / "out" / "log.yaml");
  const std::string yaml{std::istreambuf_iterator<char>(sidecar), {}};
  EXPECT_NE(yaml.find("robot: nao_motoflex_2011"), std::string::npos) << yaml;

  expect_one_line_error(run_motoflex("import-motoflex " + (dir / "walk.csv").string() + " --out " +
                                     (dir / "x.csv").string() + " --clock fast"),
                        "--clock");
  write_text(dir / "bad.csv", std::string(kCommands) + "0;0;0\n");
  expect_one_line_error(run_motoflex("import-motoflex " + (dir / "bad.csv").string() + " --out " +
                                     (dir / "x.csv").string()),
                        "bad.csv:6: expected 10");
  EXPECT_FALSE(fs::exists(dir / "x.csv"));
}

TEST(SimulateTruthAndCommandFiles, BothRunAsGiven) {
  const fs::path dir = fresh_dir("simulate_truth");
  // The truth file of reference_data/nao, simulated as `record` does (here its first 0.3 s).
  const auto truth = run_motoflex("simulate " + kSource +
                                  "/scenarios/truth/nao_motoflex.yaml --duration 0.3 --out " +
                                  (dir / "truth.csv").string());
  ASSERT_EQ(truth.exit_code, 0) << truth.stderr_text;
  const auto summary = nlohmann::json::parse(truth.stdout_text);
  EXPECT_EQ(summary["servo"], "motoflex");
  EXPECT_EQ(summary["end"], "completed");
  // A command file of the original straight into simulate, on the 2011 robot.
  write_text(dir / "walk.csv", kCommands);
  write_text(dir / "scenario.yaml",
             "robot: " + kSource + "/scenarios/robots/nao_motoflex_2011\nservo: ideal\n");
  const auto replay =
      run_motoflex("simulate " + (dir / "scenario.yaml").string() + " --motion " +
                   (dir / "walk.csv").string() + " --out " + (dir / "replay.csv").string());
  ASSERT_EQ(replay.exit_code, 0) << replay.stderr_text;
  EXPECT_EQ(nlohmann::json::parse(replay.stdout_text)["frames"], 4);
  expect_one_line_error(
      run_motoflex("simulate " + kSource + "/scenarios/truth/nao_motoflex.yaml --recording x " +
                   "--out " + (dir / "x.csv").string()),
      "no recording 'x'");
}

// simulate on a truth file is `record` for one recording: the committed reference log's
// encoders, written with 9 significant digits, come back to that precision (measured over the
// whole 10 s: 4.7e-9 relative; here the first 2 s).
TEST(SimulateTruthAndCommandFiles, ATruthRecordingReproducesTheReferenceData) {
  const fs::path dir = fresh_dir("simulate_truth_reference");
  const auto result = run_motoflex("simulate " + kSource +
                                   "/scenarios/truth/nao_motoflex.yaml --recording "
                                   "train/walk_050mm_2s --duration 2 --out " +
                                   (dir / "walk.csv").string());
  ASSERT_EQ(result.exit_code, 0) << result.stderr_text;
  JointLogRequirements need;
  need.need_measured = true;
  const JointLog ours = read_joint_log((dir / "walk.csv").string(), need);
  const JointLog reference =
      read_joint_log(kSource + "/reference_data/nao/train/walk_050mm_2s.csv", need);
  ASSERT_EQ(ours.frames(), 201u);
  ASSERT_EQ(ours.joint_names, reference.joint_names);
  double worst = 0.0;
  for (std::size_t i = 0; i < ours.measured_rad.size(); ++i) {
    const double r = reference.measured_rad[i];
    worst = std::max(worst, std::abs(ours.measured_rad[i] - r) / std::max(std::abs(r), 1e-9));
  }
  EXPECT_LT(worst, 1e-8);
}

TEST(ExperimentSeed001, RunsAStudyFileAndRefusesAnUnknownOne) {
  const fs::path dir = fresh_dir("experiment_seed001");
  write_text(dir / "walk.yaml",
             "motion:\n  walk: {speed_mm_s: 50, step_duration_s: 2, duration_s: 8}\n");
  write_text(dir / "study.yaml",
             "walks:\n  - {name: w, scenario: walk.yaml, figure: roll}\n"
             "variants:\n  - {name: rigid, scenario: " +
                 kSource + "/scenarios/experiments/seed001/rigid.yaml}\n");
  const auto result = run_motoflex("experiment " + (dir / "study.yaml").string() + " --out " +
                                   (dir / "out").string());
  ASSERT_EQ(result.exit_code, 0) << result.stderr_text;
  const auto summary = nlohmann::json::parse(result.stdout_text);  // the plots print nothing
  EXPECT_EQ(summary["w"]["rigid"]["fell"], false);
  EXPECT_TRUE(fs::exists(dir / "out" / "seed001.json"));
  // The Fig. 4-style roll plot (scripts/plot_seed001.py; matplotlib is a set-up dependency).
  EXPECT_EQ(result.stderr_text.find("no plot"), std::string::npos) << result.stderr_text;
  const fs::path png = dir / "out" / "fig4_roll_w.png";
  EXPECT_GT(fs::exists(png) ? fs::file_size(png) : 0u, 1000u) << png;
  expect_one_line_error(run_motoflex("experiment seed999 --out " + (dir / "x").string()),
                        "seed999");
}

}  // namespace
}  // namespace motoflex::testing
