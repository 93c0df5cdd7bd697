// `motoflex experiment seed001` below the command line: the metrics of a run (steady window cut
// at a fall, fall direction), the ZMP choice rule, the config's errors, and a short study on the
// rigid model whose numbers and JSON shape are checked and which does not depend on the thread
// count.

#include "motoflex/studies/seed001/seed001_study.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <optional>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/studies/seed001/seed001_config.hpp"
#include "motoflex/studies/seed001/seed001_report.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// A synthetic rollout: torso at 0.1 m/s, pitch alternating 0.02/0.04 rad per 0.5 s step, a fall
// to the right at 3.27 s.
RolloutResult synthetic_fall() {
  RolloutResult r;
  for (int i = 0; i * 0.01 <= 3.265; ++i) {
    const double t = i * 0.01;
    const int k = static_cast<int>(std::floor(t / 0.5));
    r.time_s.push_back(t);
    r.torso_position_m.insert(r.torso_position_m.end(), {0.1 * t, 0.002 * t, 0.3});
    r.imu_pitch_rad.push_back((k % 2 == 0 ? 0.02 : 0.04) *
                              std::sin(2 * std::numbers::pi * t / 0.5));
    r.imu_roll_rad.push_back(t > 3.1 ? 0.9 : 0.01);
  }
  r.frames_completed = r.time_s.size();
  r.end = RolloutEnd::kFell;
  r.end_time_s = 3.27;
  return r;
}

TEST(Seed001Study, AFallCutsTheSteadyPartToWholeStepsAndNamesItsDirection) {
  const Seed001Run run = evaluate_walk_run(synthetic_fall(), 1.0, 4.0, 0.5);
  EXPECT_TRUE(run.fell);
  EXPECT_DOUBLE_EQ(run.fall_s, 3.27);
  EXPECT_DOUBLE_EQ(run.steady_end_s, 3.0);  // last step boundary before the fall
  EXPECT_NEAR(run.speed_mm_s, 100.0, 1e-9);
  EXPECT_NEAR(run.mean_speed_mm_s, 100.0, 1e-9);  // 1 s to the end (< 9 s)
  ASSERT_TRUE(run.fall_direction.has_value());
  EXPECT_EQ(*run.fall_direction, FallDirection::kRight);
  EXPECT_NEAR(run.pitch_alternation, 2.0, 0.01);  // windows of 0.01 s samples: near the peaks
  EXPECT_NEAR(run.max_abs_roll_rad, 0.9, 1e-12);
  // Falling within the first gait cycle of the steady part leaves no steady speed.
  const Seed001Run early = evaluate_walk_run(synthetic_fall(), 2.5, 6.0, 0.5);
  EXPECT_TRUE(std::isnan(early.speed_mm_s));
  EXPECT_TRUE(std::isnan(early.pitch_alternation));
}

TEST(Seed001Study, TheChosenZmpWalksWithTheSmallestRoll) {
  std::vector<Seed001ZmpTrial> trials(5);
  const double values[] = {0.02, 0.01, 0.0, -0.01, 0.5};
  const double rolls[] = {0.05, 0.03, 0.02, 0.01, 0.0};
  for (int i = 0; i < 5; ++i) {
    trials[i].setting = {i < 4 ? "zmp_offset_y_m" : "zmp_transfer_smoothing", values[i]};
    trials[i].run.max_abs_roll_rad = rolls[i];
  }
  trials[3].run.fell = true;                   // smallest roll, but it falls
  trials[4].run.unplannable = "out of reach";  // never ran
  EXPECT_EQ(choose_zmp_trial(trials), 2);
  for (auto& trial : trials) trial.run.fell = true;
  EXPECT_EQ(choose_zmp_trial(trials), -1);
}

fs::path write_study(const fs::path& dir) {
  const std::string source = MOTOFLEX_SOURCE_DIR;
  // The 50 mm/s, 2 s walk, shortened to 8 s (start 1 s, three gait cycles, stop 1 s).
  write_text(dir / "walk.yaml",
             "motion:\n  walk: {speed_mm_s: 50, step_duration_s: 2, "
             "duration_s: 8, rate_hz: 100}\n");
  write_text(dir / "study.yaml",
             "walks:\n  - {name: short_50_2, scenario: walk.yaml, figure: roll}\n"
             "variants:\n  - {name: rigid, scenario: " +
                 source +
                 "/scenarios/experiments/seed001/rigid.yaml}\n"
                 "  - {name: later, pending: not yet}\n"
                 "zmp: {walk: short_50_2, search: {zmp_offset_y_m: [0.02, 0.0], "
                 "zmp_transfer_smoothing: [1]}, variants: [rigid, later]}\n");
  return dir / "study.yaml";
}

TEST(Seed001Study, AShortStudyOnTheRigidModel) {
  const fs::path dir = fresh_dir("seed001_study");
  const Seed001Config config = load_seed001_config(write_study(dir).string());
  const Seed001Results one = run_seed001(config, 1);
  const Seed001Results two = run_seed001(config, 2);
  ASSERT_EQ(one.runs.size(), 2u);
  const Seed001Run& rigid = one.runs[0];
  EXPECT_FALSE(rigid.fell);
  EXPECT_TRUE(std::isnan(rigid.fall_s));
  EXPECT_EQ(rigid.steady_start_s, 3.0);  // the end of the first full step (1 + 2 × 1 s)
  EXPECT_EQ(rigid.steady_end_s, 6.0);    // the start of the closing step
  // Ideal servos walk the plan: measured 52.0 mm/s over the steady part (the plan's CoM: 50),
  // pitch alternation 1.006, peak roll 0.0003 rad.
  EXPECT_NEAR(rigid.speed_mm_s, 50.0, 5.0);
  EXPECT_NEAR(rigid.pitch_alternation, 1.0, 0.05);
  EXPECT_LT(rigid.max_abs_roll_rad, 0.003);
  EXPECT_EQ(one.runs[1].pending, "not yet");
  const nlohmann::ordered_json a = seed001_json(config, one);
  EXPECT_EQ(a.dump(), seed001_json(config, two).dump());
  EXPECT_TRUE(a["short_50_2"]["rigid"]["fall_s"].is_null());
  EXPECT_EQ(a["short_50_2"]["later"]["pending"], "not yet");
  ASSERT_TRUE(one.zmp.has_value());
  EXPECT_EQ(one.zmp->variants, std::vector<std::string>{"rigid"});  // pending ones skipped
  ASSERT_EQ(one.zmp->defaults.size(), 2u);
  EXPECT_EQ(one.zmp->defaults[0].value, 0.02);  // the planner's default zmp_offset_y_m
  EXPECT_EQ(one.zmp->defaults[1].value, 0.0);
  const auto& trials = a["zmp_experiment"]["variants"]["rigid"]["trials"];
  ASSERT_EQ(trials.size(), 3u);
  // zmp_offset_y_m 0 puts RAnkleRoll beyond its limit: the planner refuses, the search goes on.
  EXPECT_NE(trials[1]["unplannable"].get<std::string>().find("RAnkleRoll"), std::string::npos)
      << trials[1];
  EXPECT_EQ(trials[2]["option"], "zmp_transfer_smoothing");
  EXPECT_EQ(trials[2]["fell"], false);
  write_seed001_report(config, one, (dir / "out").string(), false);
  EXPECT_TRUE(fs::exists(dir / "out" / "seed001.json"));
  EXPECT_TRUE(fs::exists(dir / "out" / "series" / "short_50_2__rigid.csv"));
  EXPECT_TRUE(fs::exists(dir / "out" / "series" / "zmp__rigid__2.csv"));
  EXPECT_FALSE(fs::exists(dir / "out" / "series" / "zmp__rigid__1.csv"));  // unplannable
}

// A command file in the 2011 program's format (written here): a crouch from the zero pose,
// then held for 2 s (one row per 20 ms; LHipRoll and LAnkleRoll mirrored in the file).
void write_crouch_commands(const fs::path& path) {
  std::string text =
      "LHipRoll;LHipPitch;LKneePitch;LAnklePitch;LAnkleRoll;RHipRoll;RHipPitch;RKneePitch;"
      "RAnklePitch;RAnkleRoll\n";
  for (int row = 0; row < 100; ++row) {
    const double s = std::min(1.0, row / 25.0);  // the crouch over the first 0.5 s
    const double hip = -0.4 * s, knee = 0.8 * s, ankle = -0.4 * s;
    char line[256];
    std::snprintf(line, sizeof line, "0;%.6f;%.6f;%.6f;0;0;%.6f;%.6f;%.6f;0\n", hip, knee, ankle,
                  hip, knee, ankle);
    text += line;
  }
  write_text(path, text);
}

TEST(Seed001Study, ACommandFileWalkReplaysTheFileWithItsOwnWindowAndAnEnsemble) {
  const fs::path dir = fresh_dir("seed001_commands");
  const std::string source = MOTOFLEX_SOURCE_DIR;
  write_crouch_commands(dir / "crouch.csv");
  write_text(dir / "study.yaml",
             "walks:\n  - {name: crouch, commands: crouch.csv, step_s: 0.5, steady_s: [0.5, "
             "1.5]}\n  - {name: absent, commands: nowhere.csv, step_s: 0.5}\n"
             "variants:\n  - {name: rigid_2011, scenario: " +
                 source + "/scenarios/experiments/seed001/rigid_2011.yaml}\n");
  Seed001Config config = load_seed001_config((dir / "study.yaml").string());
  ASSERT_EQ(config.walks.size(), 2u);
  EXPECT_TRUE(config.walks[0].replays_commands());
  EXPECT_EQ(config.walks[1].steady_start_s, 1.0);  // motoflex_2011.md §1's window by default
  EXPECT_EQ(config.walks[1].steady_end_s, 9.0);
  const Seed001Ensemble ensemble{3, 1e-7};
  const Seed001Results one = run_seed001(config, 1, ensemble);
  ASSERT_EQ(one.runs.size(), 2u);
  const Seed001Run& crouch = one.runs[0];
  ASSERT_TRUE(crouch.pending.empty()) << crouch.pending;
  EXPECT_FALSE(crouch.fell);
  EXPECT_EQ(crouch.steady_start_s, 0.5);
  EXPECT_EQ(crouch.steady_end_s, 1.5);
  // Crouching in place: the torso sinks, it does not travel (measured 0.0063 mm/s).
  EXPECT_LT(std::abs(crouch.speed_mm_s), 2.0);
  EXPECT_NE(one.runs[1].pending.find("--commands absent=FILE"), std::string::npos)
      << one.runs[1].pending;
  // The replicas: the same stand with 1e-7 rad of noise on every command, each its own draw;
  // the exact solver and ideal servos are not chaotic here, so they agree to a hair (measured
  // 0.00626-0.00628 mm/s, lateral drift of a few nm, different in each).
  ASSERT_EQ(crouch.ensemble.size(), 3u);
  EXPECT_NE(crouch.ensemble[0].lateral_m, crouch.ensemble[1].lateral_m);
  for (const Seed001Replica& replica : crouch.ensemble) {
    EXPECT_FALSE(replica.fell);
    EXPECT_NEAR(replica.speed_mm_s, crouch.speed_mm_s, 1e-3);
  }
  const nlohmann::ordered_json a = seed001_json(config, one);
  EXPECT_EQ(a.dump(), seed001_json(config, run_seed001(config, 2, ensemble)).dump());
  EXPECT_EQ(a["crouch"]["rigid_2011"]["ensemble"]["size"], 3);
  EXPECT_EQ(a["crouch"]["rigid_2011"]["ensemble"]["fell"], 0);
  // --commands sets a listed command-file walk's file, and refuses anything else.
  set_walk_command_file(config, "absent", (dir / "crouch.csv").string());
  EXPECT_EQ(config.walks[1].commands_path, (dir / "crouch.csv").string());
  EXPECT_THROW(set_walk_command_file(config, "nobody", "x.csv"), InputError);
}

// --seed-ensemble: replicas of a quick-step variant with the rows shuffled in another order
// (physics.quickstep_seed 1..N), none for a variant with the exact solver, which has no order.
TEST(Seed001Study, AQuickStepVariantGetsReplicasWithOtherRowOrders) {
  const fs::path dir = fresh_dir("seed001_seed_ensemble");
  const std::string source = MOTOFLEX_SOURCE_DIR;
  write_crouch_commands(dir / "crouch.csv");
  write_text(
      dir / "study.yaml",
      "walks:\n  - {name: crouch, commands: crouch.csv, step_s: 0.5, steady_s: [0.5, "
      "1.5]}\nvariants:\n  - {name: exact, scenario: " +
          source + "/scenarios/experiments/seed001/rigid_2011.yaml}\n  - {name: quick, scenario: " +
          source + "/scenarios/experiments/seed001/rigid_2011.yaml, physics: {solver: quick}}\n");
  const Seed001Config config = load_seed001_config((dir / "study.yaml").string());
  Seed001Ensemble ensemble;
  ensemble.quickstep_seeds = 2;
  const Seed001Results results = run_seed001(config, 2, ensemble);
  ASSERT_EQ(results.runs.size(), 2u);
  const Seed001Run& exact = results.runs[0];
  const Seed001Run& quick = results.runs[1];
  ASSERT_EQ(quick.variant, "quick");
  EXPECT_TRUE(exact.seed_ensemble.empty());
  EXPECT_TRUE(quick.ensemble.empty());
  ASSERT_EQ(quick.seed_ensemble.size(), 2u);
  // Each order is its own answer of the unconverged quick step: the stand drifts sideways by a
  // different few nm, and travels no more than the run itself does.
  EXPECT_NE(quick.seed_ensemble[0].lateral_m, quick.seed_ensemble[1].lateral_m);
  EXPECT_NE(quick.seed_ensemble[0].lateral_m, quick.lateral_m);
  for (const Seed001Replica& replica : quick.seed_ensemble) {
    EXPECT_FALSE(replica.fell);
    EXPECT_LT(std::abs(replica.speed_mm_s), 2.0);
  }
  const nlohmann::ordered_json j = seed001_json(config, results);
  EXPECT_EQ(j["crouch"]["quick"]["quickstep_seed_ensemble"]["size"], 2);
  EXPECT_FALSE(j["crouch"]["exact"].contains("quickstep_seed_ensemble"));
  // Seeds, not threads, decide: one thread gives the same replicas.
  EXPECT_EQ(j.dump(), seed001_json(config, run_seed001(config, 1, ensemble)).dump());
}

// Writes `text` as dir/bad.yaml and returns the InputError loading it throws (a test failure,
// and nothing, when it loads).
std::optional<InputError> config_error(const fs::path& dir, const std::string& text) {
  write_text(dir / "bad.yaml", text);
  try {
    load_seed001_config((dir / "bad.yaml").string());
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "no error for:\n" << text;
  return std::nullopt;
}

TEST(Seed001Study, ConfigErrorsNameTheirField) {
  const fs::path dir = fresh_dir("seed001_config");
  write_study(dir);
  if (const auto error = config_error(
          dir, "walks:\n  - {name: w, scenario: walk.yaml, figure: yaw}\nvariants: []\n")) {
    EXPECT_EQ(error->line(), 2) << error->what();
    EXPECT_NE(error->message().find("pitch"), std::string::npos) << error->what();
  }
  write_text(dir / "bad.yaml",
             "walks:\n  - {name: w, scenario: walk.yaml}\nvariants:\n"
             "  - {name: v, pending: x}\nzmp: {walk: w, search: {zmp_offset_y_m: [0]}, "
             "variants: [nobody]}\n");
  EXPECT_THROW(load_seed001_config((dir / "bad.yaml").string()), InputError);
  // A walk is planned or replayed, not both; a command file needs its step; the ZMP experiment
  // needs a planned walk.
  write_text(dir / "bad.yaml",
             "walks:\n  - {name: w, scenario: walk.yaml, commands: c.csv, step_s: 1}\n"
             "variants:\n  - {name: v, pending: x}\n");
  EXPECT_THROW(load_seed001_config((dir / "bad.yaml").string()), InputError);
  write_text(dir / "bad.yaml",
             "walks:\n  - {name: w, commands: c.csv}\nvariants:\n  - {name: v, pending: x}\n");
  EXPECT_THROW(load_seed001_config((dir / "bad.yaml").string()), InputError);
  if (const auto error = config_error(
          dir,
          "walks:\n  - {name: w, commands: c.csv, step_s: 1}\nvariants:\n"
          "  - {name: v, pending: x}\nzmp: {walk: w, search: {zmp_offset_y_m: [0.02]}, "
          "variants: [v]}\n")) {
    EXPECT_NE(error->message().find("planned walk"), std::string::npos) << error->what();
  }
  // A walk's own variant list names variants of the file, and the ZMP walk's includes the
  // ZMP experiment's.
  if (const auto error = config_error(
          dir,
          "walks:\n  - {name: w, scenario: walk.yaml, variants: [v, nobody]}\nvariants:\n"
          "  - {name: v, pending: x}\n")) {
    EXPECT_EQ(error->field(), "walks[0].variants") << error->what();
    EXPECT_NE(error->message().find("'nobody' is not a variant"), std::string::npos)
        << error->what();
  }
  if (const auto error =
          config_error(dir,
                       "walks:\n  - {name: w, scenario: walk.yaml, variants: [v]}\nvariants:\n"
                       "  - {name: v, pending: x}\n  - {name: u, pending: y}\n"
                       "zmp: {walk: w, search: {zmp_offset_y_m: [0.02]}, variants: [u]}\n")) {
    EXPECT_NE(error->message().find("not among walk 'w''s variants"), std::string::npos)
        << error->what();
  }
  EXPECT_THROW(find_experiment_config("no_such_experiment"), InputError);
  EXPECT_NO_THROW(find_experiment_config("seed001"));
}

// A walk with its own variant list runs under those variants only: no run, not even a pending
// one, for the others.
TEST(Seed001Study, AWalkRunsUnderItsOwnVariantsOnly) {
  const fs::path dir = fresh_dir("seed001_walk_variants");
  write_study(dir);
  write_text(
      dir / "only.yaml",
      "walks:\n  - {name: short_50_2, scenario: walk.yaml}\n"
      "  - {name: again, scenario: walk.yaml, variants: [later]}\n"
      "variants:\n  - {name: rigid, pending: not here}\n  - {name: later, pending: not yet}\n");
  const Seed001Results results = run_seed001(load_seed001_config((dir / "only.yaml").string()), 1);
  ASSERT_EQ(results.runs.size(), 3u);
  EXPECT_EQ(results.runs[0].variant, "rigid");
  EXPECT_EQ(results.runs[1].variant, "later");
  EXPECT_EQ(results.runs[2].walk, "again");
  EXPECT_EQ(results.runs[2].variant, "later");
}

// A variant's `physics:` keys go on top of its scenario's: the same crouch on the 2011 box robot
// with the bodies' state rounded to floats (physics.float_state) is another rollout, equal to
// float resolution; a pending variant has no physics, and a bad key is the variant's error.
TEST(Seed001Study, AVariantsPhysicsKeysGoOnTopOfItsScenario) {
  const fs::path dir = fresh_dir("seed001_variant_physics");
  const std::string rigid_2011 =
      std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/experiments/seed001/rigid_2011.yaml";
  write_crouch_commands(dir / "crouch.csv");
  write_text(dir / "study.yaml",
             "walks:\n  - {name: crouch, commands: crouch.csv, step_s: 0.5, steady_s: [0.5, "
             "1.5]}\nvariants:\n  - {name: exact, scenario: " +
                 rigid_2011 + "}\n  - {name: float, scenario: " + rigid_2011 +
                 ", physics: {float_state: true}}\n");
  const Seed001Config config = load_seed001_config((dir / "study.yaml").string());
  ASSERT_TRUE(config.variants[1].physics.has_value());
  EXPECT_FALSE(config.variants[0].physics.has_value());
  const Seed001Results results = run_seed001(config, 2);
  ASSERT_EQ(results.runs.size(), 2u);
  const Seed001Run& exact = results.runs[0];
  const Seed001Run& rounded = results.runs[1];
  ASSERT_TRUE(exact.pending.empty() && rounded.pending.empty());
  EXPECT_FALSE(rounded.fell);
  EXPECT_NE(rounded.lateral_m, exact.lateral_m);
  EXPECT_NEAR(rounded.speed_mm_s, exact.speed_mm_s, 1e-2);
  write_text(dir / "bad.yaml",
             "walks:\n  - {name: w, commands: c.csv, step_s: 1}\nvariants:\n"
             "  - {name: v, pending: x, physics: {float_state: true}}\n");
  EXPECT_THROW(load_seed001_config((dir / "bad.yaml").string()), InputError);
  write_text(dir / "bad.yaml",
             "walks:\n  - {name: crouch, commands: crouch.csv, step_s: 0.5}\nvariants:\n"
             "  - {name: v, scenario: " +
                 rigid_2011 + ", physics: {float_state: maybe}}\n");
  EXPECT_THROW(run_seed001(load_seed001_config((dir / "bad.yaml").string()), 1), InputError);
}

}  // namespace
}  // namespace motoflex::testing
