// Truth files (the input of `motoflex record`) load as scenarios: the recording's scenario with
// the truth's servo, physics and parameters, the recording's own sensor seed; a motion of another
// file (a walk, a command log) replaces the recording's, and a parameter file given by the caller
// wins over the truth. What `simulate TRUTH.yaml` and the seed-001 experiment rely on.

#include "motoflex/scenario/truth_file.hpp"

#include <gtest/gtest.h>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/random_stream.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const std::string kTruth = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/truth/nao_motoflex.yaml";
const std::string kWalks = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/walks/";

TEST(TruthFile, NaoMotoflexLoadsAsItsFirstRecordingWithTheTruthApplied) {
  ASSERT_TRUE(is_truth_file(kTruth));
  EXPECT_FALSE(is_truth_file(kWalks + "nao_walk_50_2.yaml"));
  const Scenario s = load_scenario_or_truth(kTruth);
  EXPECT_EQ(s.name, "nao_walk_50_2");  // train/walk_050mm_2s
  EXPECT_EQ(s.rollout.servo, "motoflex");
  EXPECT_EQ(s.model->structure.flex_sub_bodies, 2);
  EXPECT_EQ(s.rollout.gear_substeps, 100);
  EXPECT_EQ(s.parameters.get("pid.kp_v_per_rad"), 319.4724);
  EXPECT_EQ(s.parameters.get("sensor.resolution_bits"), 12.0);
  EXPECT_EQ(s.rollout.seed, mix64(2011ULL * 0x100000001B3ULL + 0));
  ASSERT_NE(s.walk_plan, nullptr);
  EXPECT_EQ(s.walk_plan->params.speed_mm_s, 50.0);

  const Scenario kick = load_scenario_or_truth(kTruth, {}, "train/kick");
  EXPECT_EQ(kick.name, "nao_kick");
  EXPECT_EQ(kick.rollout.seed, mix64(2011ULL * 0x100000001B3ULL + 4));
  try {
    load_scenario_or_truth(kTruth, {}, "train/nothing");
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("train/kick"), std::string::npos) << error.what();
  }
}

TEST(TruthFile, AnotherMotionAndWalkOptionsReplaceTheRecordingsAndCallerParametersWin) {
  const fs::path dir = fresh_dir("truth_file");
  write_text(dir / "p.json", "{\"pid.kp_v_per_rad\": 100.0}");
  ScenarioOverrides overrides;
  overrides.motion_scenario = kWalks + "nao_walk_200_1.yaml";
  overrides.walk_options = {{"zmp_offset_y_m", 0.0}};
  overrides.parameters_json = (dir / "p.json").string();
  const Scenario s = load_scenario_or_truth(kTruth, overrides);
  ASSERT_NE(s.walk_plan, nullptr);
  EXPECT_EQ(s.walk_plan->params.speed_mm_s, 200.0);
  EXPECT_EQ(s.walk_plan->params.zmp_offset_y_m, 0.0);
  EXPECT_NE(s.motion_description.find("zmp_offset_y_m 0"), std::string::npos)
      << s.motion_description;
  EXPECT_EQ(s.parameters.get("pid.kp_v_per_rad"), 100.0);
  EXPECT_EQ(s.parameters.get("pid.kd_v_s_per_rad"), 0.1635552);  // the truth's

  overrides.walk_options = {{"zmp_wobble", 1.0}};
  try {
    load_scenario_or_truth(kTruth, overrides);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(error.message().find("zmp_wobble"), std::string::npos) << error.what();
  }
}

TEST(TruthFile, BadKeysAreErrorsAtTheirLine) {
  const fs::path dir = fresh_dir("truth_file_bad");
  write_text(dir / "t.yaml", "seed: 1\ndigitz: 3\nrecordings: []\n");
  try {
    load_truth_file((dir / "t.yaml").string());
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), 2) << error.what();
  }
  write_text(dir / "t.yaml", "recordings:\n  - {name: ../up, scenario: x.yaml}\n");
  EXPECT_THROW(load_truth_file((dir / "t.yaml").string()), InputError);
}

}  // namespace
}  // namespace motoflex::testing
