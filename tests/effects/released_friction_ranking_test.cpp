// A released arm that swings on longer than the powered joint's friction allows is traced to
// the effect released_friction. Three lift-and-drop logs of the XL330 bench (the arm lifted to
// −π/2 in 2 s at kp 100, 400 and 800, then released until 6 s) are recorded with a released
// Coulomb level a quarter of the powered one and a larger released viscous coefficient, as the
// real XL330's released swings show (README, the released arm). Ranked at that truth with the
// released levels reset to the powered ones (no fit involved), the effect ranks first, is
// supported by ΔBIC, and its linearised estimate lowers the released Coulomb level; at the whole
// truth it explains nothing.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/effects/effect_signature.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/model/parameters.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/sim/rollout.hpp"
#include "sim/bench_stall_support.hpp"

namespace motoflex::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kLogDt_s = 0.005;
constexpr double kRelease_s = 2.0;
constexpr double kCoulombDelta_nm = -0.03;  // powered 0.04 N·m, released 0.01
constexpr double kViscousDelta = 0.006;     // powered 0.003 N·m·s/rad, released 0.009

void set_truth(ParameterSet& p, bool released) {
  p.set("bench.logged_supply", 0.0);
  p.set("bench.Kt_nm_per_a", 0.35);
  p.set("bench.R_ohm", 2.7);
  p.set("bench.armature_kg_m2", 0.0016);
  p.set("joint.pendulum.friction_nm", 0.04);
  p.set("joint.pendulum.viscous_nm_s_per_rad", 0.003);
  p.set("joint.pendulum.released_friction_delta_nm", released ? kCoulombDelta_nm : 0.0);
  p.set("joint.pendulum.released_viscous_delta_nm_s_per_rad", released ? kViscousDelta : 0.0);
}

// BAM's lift_and_drop goal: a cubic from 0 to −π/2 over 2 s, then held (and not followed).
double lift_goal_rad(double t_s) {
  const double u = std::min(t_s / kRelease_s, 1.0);
  return -0.5 * kPi * u * u * (3.0 - 2.0 * u);
}

// Records one log (CSV + sidecar) of the truth at gain `kp` into `folder`.
void record_lift_and_drop(const RobotModel& bench, const std::filesystem::path& folder, int kp) {
  std::vector<double> time_s, goal_rad;
  for (int k = 0; k <= 1200; ++k) {
    time_s.push_back(k * kLogDt_s);
    goal_rad.push_back(lift_goal_rad(k * kLogDt_s));
  }
  const CommandTrajectory command(time_s, goal_rad, 1);
  ParameterSet truth(bench.parameters);
  set_truth(truth, true);
  truth.set("bench.kp", kp);
  truth.set("bench.torque_off_s", kRelease_s);
  RolloutOptions options;
  options.servo = "bench";
  const RolloutResult r = run_rollout(bench, truth, command, options);
  ASSERT_EQ(r.end, RolloutEnd::kCompleted) << r.end_detail;
  const std::string name = "lift_and_drop_kp" + std::to_string(kp);
  std::ostringstream csv;
  csv.precision(17);
  csv << "time_s,pendulum.cmd,pendulum.meas\n";
  for (std::size_t f = 0; f < r.time_s.size(); ++f) {
    csv << r.time_s[f] << "," << r.commanded_rad[f] << "," << r.measured_rad[f] << "\n";
  }
  write_text(folder / (name + ".csv"), csv.str());
  write_text(folder / (name + ".yaml"),
             "robot: servo_pendulum\nrate_hz: 200\nmotion: lift_and_drop\nunits: rad\n"
             "parameters:\n  bench.kp: " +
                 std::to_string(kp) + "\n  bench.torque_off_s: " + std::to_string(kRelease_s) +
                 "\n  bench.logged_supply: 0\n");
}

FitConfig released_arm_fit() {
  const std::filesystem::path dir = fresh_dir("released_friction_ranking");
  const RobotModel bench = load_servo_pendulum();
  std::filesystem::create_directories(dir / "train");
  for (const int kp : {100, 400, 800}) record_lift_and_drop(bench, dir / "train", kp);
  write_text(dir / "fit.yaml",
             "name: released_arm\n"
             "scenario: " +
                 std::string(MOTOFLEX_SOURCE_DIR) +
                 "/scenarios/servo_pendulum_replay.yaml\n"
                 "data: " +
                 (dir / "train").string() +
                 "\nfree:\n"
                 "  bench.Kt_nm_per_a: {lower: 0.1, upper: 3.0, log: true, start: 0.6}\n"
                 "  bench.R_ohm: {lower: 2.0, upper: 5.0, start: 2.6}\n"
                 "  bench.armature_kg_m2: {lower: 1.0e-4, upper: 0.05, log: true, start: 0.005}\n"
                 "  joint.pendulum.friction_nm: {lower: 0.0, upper: 0.2, start: 0.05}\n"
                 "  joint.pendulum.viscous_nm_s_per_rad: {lower: 0.0, upper: 1.0, start: 0.05}\n"
                 "fitness: {m: 2, error: absolute}\n"
                 "budget: {evaluations: 100}\nthreads: 2\nseed: 1\n"
                 "out: " +
                 (dir / "run").string() + "\n");
  return load_fit_config((dir / "fit.yaml").string());
}

TEST(ReleasedFrictionRanking, ALongerReleasedSwingRanksReleasedFrictionFirst) {
  const FitConfig config = released_arm_fit();
  ParameterSet current = config.space->base();
  set_truth(current, false);
  const EffectRanking ranking = rank_effects(config, current, {}, 2);
  ASSERT_FALSE(ranking.scores.empty());
  for (std::size_t k = 0; k < 4 && k < ranking.scores.size(); ++k) {
    std::printf("rank %zu: %s explained %.3f, delta BIC %.2f\n", k + 1,
                ranking.scores[k].effect.c_str(), ranking.scores[k].explained,
                ranking.scores[k].delta_bic);
  }
  const EffectScore& top = ranking.scores.front();
  EXPECT_EQ(top.effect, "released_friction");
  EXPECT_LT(top.delta_bic, 0.0);
  double estimate_nm = 0.0;
  for (const auto& [name, value] : top.estimate) {
    if (name == "joint.pendulum.released_friction_delta_nm") estimate_nm = value;
  }
  std::printf("released Coulomb change: estimate %.4f N·m, truth %.4f\n", estimate_nm,
              kCoulombDelta_nm);
  // The swing's response to the released friction is far from linear (each half swing loses
  // 2·K_c/(m·g·l) of amplitude until the arm sticks), so the linearised estimate falls short of
  // the truth (measured −0.0083 N·m against −0.03); it points the refit's search the right way.
  EXPECT_LT(estimate_nm, 0.2 * kCoulombDelta_nm);
  EXPECT_GT(estimate_nm, 1.5 * kCoulombDelta_nm);
  if (ranking.scores.size() > 1) {
    EXPECT_LT(ranking.scores[1].explained, 0.5 * top.explained) << ranking.scores[1].effect;
  }

  ParameterSet truth = config.space->base();
  set_truth(truth, true);
  const EffectRanking at_truth = rank_effects(config, truth, {"released_friction"}, 2);
  ASSERT_EQ(at_truth.scores.size(), 1u);
  std::printf("at the truth: explained %.2e\n", at_truth.scores.front().explained);
  EXPECT_LT(at_truth.scores.front().explained, 0.01);
}

}  // namespace
}  // namespace motoflex::testing
