// motoflex loop end to end on logs with an undeclared effect (reference_data/hidden/): from the
// base model that lacks it, the loop ranks the true effect first, adds it, and the validation
// RMS falls by at least half or to within 1.2x the noise floor; on logs with nothing missing it
// adds nothing. And on the real servo logs of ../shared/data/bam (skipped when absent): the
// validation MAE after the loop is below the M1 fit's.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "bam_data.hpp"
#include "cli/cli_test_support.hpp"
#include "effect_test_support.hpp"
#include "fit/fit_test_support.hpp"
#include "motoflex/effects/effect_loop.hpp"
#include "motoflex/fit/fit_run.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

// The bench fits stop at their evaluation budget, before CMA-ES's own tolerances: the loop is
// forced on (its rankings are then marked unreliable), as these tests are about what it finds.
constexpr bool kForceUnconverged = true;

const char* kOneStep =
    "{candidates: 2, max_iterations: 1, min_gain: 0.05, refit: {strategy: "
    "{kind: cma_es, sigma: 0.03, restarts: 0}, budget: {evaluations: 240}}}";

class HiddenEffectLoop : public ::testing::TestWithParam<const char*> {};

TEST_P(HiddenEffectLoop, FindsAddsAndFixesTheEffect) {
  const std::string effect = GetParam();
  const fs::path dir = fresh_dir("loop_" + effect);
  const std::string fit = write_hidden_bench_fit(dir, effect, kOneStep);
  const LoopResult result = run_loop(fit, {}, kForceUnconverged);
  ASSERT_EQ(result.iterations.size(), 1u);
  const LoopIteration& it = result.iterations.front();
  ASSERT_FALSE(it.ranking.scores.empty());
  EXPECT_EQ(it.ranking.scores.front().effect, effect);
  EXPECT_EQ(it.added_effect, effect);
  const double floor_deg = noise_floor_deg(load_fit_config(fit), effect);
  const double target = std::max(0.5 * it.val_rms_before_deg, 1.2 * floor_deg);
  EXPECT_LE(it.val_rms_after_deg, target)
      << effect << ": " << it.val_rms_before_deg << " -> " << it.val_rms_after_deg
      << " deg, noise floor " << floor_deg;
  EXPECT_EQ(result.final_model.back(), effect);

  // The run dir documents it.
  const nlohmann::json loop = nlohmann::json::parse(read_text(dir / "run" / "loop.json"));
  EXPECT_EQ(loop["iterations"][0]["added_effect"], effect);
  EXPECT_EQ(loop["iterations"][0]["ranking"][0]["effect"], effect);
  EXPECT_EQ(loop["iterations"][0]["unit"], "deg");
  // The options it ran with (kOneStep, the config's seed), whatever the config file says later.
  EXPECT_EQ(loop["options"]["candidates"], 2);
  EXPECT_EQ(loop["options"]["max_iterations"], 1);
  EXPECT_EQ(loop["options"]["refit"]["budget"]["evaluations"], 240);
  EXPECT_EQ(loop["options"]["seed"], 1);
  // A bench has no torso IMU: its zero IMU columns are matched exactly and not reported.
  EXPECT_EQ(read_text(dir / "run" / "report.md").find("Torso IMU"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(BenchEffects, HiddenEffectLoop,
                         ::testing::Values("encoder_offset", "sensor_delay", "stribeck",
                                           "load_friction", "resistance_drift"));

// A torque that saturates with the current (reference_data/hidden/torque_saturation, k = 0.8 /A)
// has a near relative in the library, the driver's hard current limit: from the base fit that
// lacks both, the limit ranks first (measured ΔBIC −3.8 against −0.7) and both refits pass.
// The loop must add the saturation, which validates better, not the first-ranked limit.
TEST(HiddenEffectLoopTorqueSaturation, AddsTheSaturationOverTheCurrentLimitRankedAboveIt) {
  const fs::path dir = fresh_dir("loop_torque_saturation");
  const std::string fit = write_hidden_bench_fit(dir, "torque_saturation", kOneStep);
  const LoopResult result = run_loop(fit, {}, kForceUnconverged);
  ASSERT_EQ(result.iterations.size(), 1u);
  const LoopIteration& it = result.iterations.front();
  ASSERT_GE(it.ranking.scores.size(), 2u);
  std::vector<std::string> top_two = {it.ranking.scores[0].effect, it.ranking.scores[1].effect};
  std::sort(top_two.begin(), top_two.end());
  EXPECT_EQ(top_two, (std::vector<std::string>{"current_limit", "torque_saturation"}));
  EXPECT_EQ(it.added_effect, "torque_saturation");
  const double floor_deg = noise_floor_deg(load_fit_config(fit), "torque_saturation");
  EXPECT_LE(it.val_rms_after_deg, std::max(0.5 * it.val_rms_before_deg, 1.2 * floor_deg))
      << it.val_rms_before_deg << " -> " << it.val_rms_after_deg << " deg, noise floor "
      << floor_deg;
  std::printf("torque_saturation: validation RMS %.4f -> %.4f deg (noise floor %.4f)\n",
              it.val_rms_before_deg, it.val_rms_after_deg, floor_deg);
}

// Nothing is missing: no effect is added. The iteration's first refit is the control (the base
// model refit alone); the base fit stopped on its budget, so the control may validate better,
// and then the loop goes on from it as re-optimised, never crediting an effect with that gain.
TEST(HiddenEffectLoopNone, AddsNothingWhenNothingIsMissing) {
  const fs::path dir = fresh_dir("loop_none");
  const LoopResult result =
      run_loop(write_hidden_bench_fit(dir, "none", kOneStep), {}, kForceUnconverged);
  ASSERT_EQ(result.iterations.size(), 1u);
  const LoopIteration& it = result.iterations.front();
  EXPECT_TRUE(it.added_effect.empty());
  EXPECT_EQ(result.final_model, result.base_model);
  ASSERT_FALSE(it.refits.empty());
  EXPECT_EQ(it.refits.front().effect, "control");
  for (const LoopRefit& refit : it.refits) EXPECT_FALSE(refit.significant) << refit.effect;
  if (it.reoptimised) {
    const auto from = std::find_if(it.refits.begin(), it.refits.end(), [&](const LoopRefit& r) {
      return r.effect == it.reoptimised_from;
    });
    ASSERT_NE(from, it.refits.end()) << it.reoptimised_from;
    EXPECT_TRUE(from->reoptimises);
    EXPECT_TRUE(from->effect == "control" || from->inert) << from->effect;
    // Carried over without the inert effect's parameters, the model validates as that refit did.
    EXPECT_NEAR(it.val_rms_after_deg, from->val_rms_deg, 1e-12);
  } else {
    EXPECT_EQ(it.val_rms_after_deg, it.val_rms_before_deg);
  }
  std::printf("none: validation RMS %.4f -> %.4f deg (%s)\n", it.val_rms_before_deg,
              it.val_rms_after_deg, it.reoptimised ? "re-optimised" : "unchanged");
}

// On logs with nothing missing, from a base fit stopped after 40 evaluations, a refit with load
// friction validates better: its wide search re-optimises the base's own parameters. Without a
// control refit the loop credits load friction with that gain (a false effect); with one, the
// control reaches the same and load friction is not added.
LoopResult unconverged_none_loop(const std::string& name, const char* control) {
  const fs::path dir = fresh_dir(name);
  const std::string loop =
      std::string("{candidates: 1, max_iterations: 1, control: ") + control +
      ", effects: [load_friction], refit: {strategy: {kind: cma_es, sigma: 0.2, restarts: 0}, "
      "budget: {evaluations: 240}}}";
  return run_loop(write_hidden_bench_fit(dir, "none", loop, "", "{evaluations: 40}"), {},
                  kForceUnconverged);
}

TEST(HiddenEffectLoopNone, TheControlRefitKeepsAReoptimisationFromBeingCreditedToAnEffect) {
  const LoopResult without = unconverged_none_loop("loop_uncontrolled", "false");
  const LoopResult with = unconverged_none_loop("loop_controlled", "true");
  ASSERT_EQ(without.iterations.size(), 1u);
  ASSERT_EQ(with.iterations.size(), 1u);
  const LoopIteration& a = without.iterations.front();
  const LoopIteration& b = with.iterations.front();
  std::printf(
      "none, base at 40 evaluations: without control %s (%.4f -> %.4f deg); with control "
      "%s%s (%.4f -> %.4f deg)\n",
      a.added_effect.empty() ? "nothing added" : ("added " + a.added_effect).c_str(),
      a.val_rms_before_deg, a.val_rms_after_deg,
      b.added_effect.empty() ? "nothing added" : ("added " + b.added_effect).c_str(),
      b.reoptimised ? ", re-optimised" : "", b.val_rms_before_deg, b.val_rms_after_deg);
  EXPECT_EQ(a.added_effect, "load_friction");  // the false effect the control is there to stop
  EXPECT_TRUE(b.added_effect.empty());
  EXPECT_EQ(with.final_model, with.base_model);
  ASSERT_GE(b.refits.size(), 2u);
  EXPECT_EQ(b.refits[0].effect, "control");
  EXPECT_FALSE(b.refits[1].significant);
  // The gain is kept all the same, as a re-optimisation of the base model.
  EXPECT_TRUE(b.reoptimised);
  EXPECT_LT(b.val_rms_after_deg, 0.95 * b.val_rms_before_deg);
}

// An effect that does not help at its refit's optimum is never added. On the Stribeck logs, from
// a base stopped after 40 evaluations and without a control, the only candidate is load
// friction: its refit re-optimises the base's own parameters and validates better, but switching
// load friction off there scores better still on the training logs, so it is inert. The loop
// goes on from the refit's values without load friction (01_reoptimised_load_friction, one
// evaluation), judged on their own validation.
TEST(HiddenEffectLoopNone, AnInertEffectIsNotAddedButItsReoptimisationIsKept) {
  const fs::path dir = fresh_dir("loop_inert");
  const std::string fit = write_hidden_bench_fit(
      dir, "stribeck",
      "{candidates: 1, max_iterations: 1, control: false, effects: [load_friction], refit: "
      "{strategy: {kind: cma_es, sigma: 0.2, restarts: 0}, budget: {evaluations: 240}}}",
      "", "{evaluations: 40}");
  const LoopResult result = run_loop(fit, {}, kForceUnconverged);
  ASSERT_EQ(result.iterations.size(), 1u);
  const LoopIteration& it = result.iterations.front();
  ASSERT_EQ(it.refits.size(), 1u);
  const LoopRefit& refit = it.refits.front();
  std::printf("inert load friction on Stribeck logs: validation RMS %.4f -> %.4f deg (refit)\n",
              it.val_rms_before_deg, refit.val_rms_deg);
  EXPECT_EQ(refit.effect, "load_friction");
  EXPECT_TRUE(refit.inert);
  EXPECT_FALSE(refit.significant);
  ASSERT_TRUE(refit.reoptimises);
  EXPECT_TRUE(it.reoptimised);
  EXPECT_EQ(it.reoptimised_from, "load_friction");
  EXPECT_TRUE(it.added_effect.empty());
  EXPECT_EQ(result.final_model, result.base_model);
  const FinishedFit final_fit = load_finished_fit(result.final_run_dir);
  EXPECT_EQ(fs::path(result.final_run_dir).filename(), "01_reoptimised_load_friction");
  EXPECT_LT(it.val_rms_after_deg, 0.95 * it.val_rms_before_deg);
  // Its training fitness is no worse than the refit's (that is what inert means).
  const FinishedFit refit_fit = load_finished_fit(refit.run_dir);
  EXPECT_LE(final_fit.summary.value("best_fitness", 1.0),
            refit_fit.summary.value("best_fitness", 0.0));
  EXPECT_EQ(final_fit.config.space->dimension(), 4u);  // the base's four: no load friction
  EXPECT_EQ(final_fit.summary.value("evaluations", 0), 1);
}

TEST(HiddenEffectLoopResume, ASecondRunReusesTheFinishedFits) {
  const fs::path dir = fresh_dir("loop_resume");
  const std::string fit = write_hidden_bench_fit(
      dir, "encoder_offset",
      "{candidates: 1, max_iterations: 1, refit: {budget: {evaluations: 60}}}", "",
      "{evaluations: 120}");
  const LoopResult first = run_loop(fit, {}, kForceUnconverged);
  // Every fit of the loop, with the time its results were written.
  std::map<fs::path, fs::file_time_type> written;
  for (const auto& entry : fs::directory_iterator(dir / "run")) {
    if (fs::exists(entry.path() / "summary.json")) {
      written[entry.path()] = fs::last_write_time(entry.path() / "summary.json");
    }
  }
  ASSERT_GE(written.size(), 2u);  // the base fit and a refit
  const LoopResult second = run_loop(fit, {}, kForceUnconverged);
  EXPECT_EQ(second.iterations.front().val_rms_after_deg,
            first.iterations.front().val_rms_after_deg);
  EXPECT_EQ(second.evaluations, first.evaluations);  // read back from the finished run dirs
  // No fit ran again: their results are the files the first run wrote.
  for (const auto& [run_dir, time] : written) {
    EXPECT_EQ(fs::last_write_time(run_dir / "summary.json"), time) << run_dir;
  }
  // Another refit budget in the same folder: the old loop moves to previous-1 and the refit
  // runs again with the new budget (LoopIdentity), instead of the old refit being reused.
  const std::string changed = write_hidden_bench_fit(
      dir, "encoder_offset",
      "{candidates: 1, max_iterations: 1, refit: {budget: {evaluations: 90}}}", "",
      "{evaluations: 120}");
  const LoopResult third = run_loop(changed, {}, kForceUnconverged);
  EXPECT_NE(third.evaluations, first.evaluations);
  EXPECT_TRUE(fs::exists(dir / "run" / "previous-1" / "loop.json"));
}

// The Nao whose thighs and tibias bend (reference_data/hidden/link_flexibility), fitted with a
// rigid model that scores the torso IMU too (scenarios/fit/nao_hidden_flex.yaml): the bending
// tilts the torso, the loop ranks link flexibility first, adds it, and the validation error falls
// by half or to the noise floor.
TEST(HiddenEffectLoopNao, FindsAddsAndFixesLinkFlexibility) {
  const fs::path dir = fresh_dir("loop_link_flexibility");
  FitOverrides overrides;
  overrides.out = (dir / "run").string();
  const LoopResult result =
      run_loop((fs::path(MOTOFLEX_SOURCE_DIR) / "scenarios/fit/nao_hidden_flex.yaml").string(),
               overrides, kForceUnconverged);
  ASSERT_EQ(result.iterations.size(), 1u);
  const LoopIteration& it = result.iterations.front();
  ASSERT_FALSE(it.ranking.scores.empty());
  EXPECT_EQ(it.ranking.scores.front().effect, "link_flexibility");
  EXPECT_EQ(it.added_effect, "link_flexibility");

  // The noise floor: the truth (flexible links) replayed without sensor noise, on the final
  // fit's flexible model.
  const FinishedFit final_fit = load_finished_fit(result.final_run_dir);
  const ParameterSet truth =
      hidden_truth("link_flexibility", "validation/squat", final_fit.config.space->base(), true);
  const double floor_deg = evaluate_in_detail(*final_fit.config.validation, truth).rms_deg;
  const double target = std::max(0.55 * it.val_rms_before_deg, 1.2 * floor_deg);
  const double spring = final_fit.best_json["free"].at("flex.spring_nm_per_rad").get<double>();
  std::printf(
      "link_flexibility: validation RMS %.4f -> %.4f deg (noise floor %.4f), IMU %.4f -> "
      "%.4f deg, spring %.1f N*m/rad (truth 150)\n",
      it.val_rms_before_deg, it.val_rms_after_deg, floor_deg, it.val_imu_rms_before_deg,
      it.val_imu_rms_after_deg, spring);
  // With the base held at the robot's nominal defaults the refit's optimum validates at half the
  // error before, and no lower: 0.1662 -> 0.0826 deg (solver step, 2026-11-25), 0.0840 (sparse,
  // 2026-11-29), 0.0830 and 0.0829 with 240- and 320-evaluation refits (ad hoc, 2026-11-29). The
  // held nominal values set that plateau, not the bending (with the base held at the truth:
  // 0.2297 -> 0.0351), so the joint test allows 55 % of the error before, and the bending itself
  // is checked where it shows: the torso IMU and the fitted spring (159 with sparse, 155 at 320).
  EXPECT_LE(it.val_rms_after_deg, target);
  EXPECT_NEAR(spring, 150.0, 15.0);
  EXPECT_LT(it.val_imu_rms_after_deg, 0.5 * it.val_imu_rms_before_deg);

  const nlohmann::json loop = nlohmann::json::parse(read_text(dir / "run" / "loop.json"));
  EXPECT_EQ(loop["iterations"][0]["added_effect"], "link_flexibility");
  EXPECT_TRUE(loop["iterations"][0].contains("val_imu_rms_after"));
  EXPECT_NE(read_text(dir / "run" / "report.md").find("Torso IMU"), std::string::npos);
}

// Real logs: BAM's XL330 bench, kp 400 held out for validation as BAM does.
TEST(RealServoLoop, BeatsTheCoulombViscousModelOnValidationLogs) {
  const fs::path bam = bam_data_or_empty("xl330/processed");
  if (bam.empty()) GTEST_SKIP() << "no BAM logs in ../shared/data/bam/xl330/processed";
  const fs::path dir = fresh_dir("loop_bam");
  fs::create_directories(dir / "train");
  fs::create_directories(dir / "validation");
  for (const auto& entry : fs::directory_iterator(bam)) {
    if (entry.path().extension() != ".json") continue;
    const nlohmann::json log = nlohmann::json::parse(read_text(entry.path()));
    const bool validation = log.value("kp", 0.0) == 400.0;
    fs::copy_file(entry.path(),
                  dir / (validation ? "validation" : "train") / entry.path().filename());
  }
  FitOverrides overrides;
  overrides.data = (dir / "train").string();
  overrides.validation = (dir / "validation").string();
  overrides.out = (dir / "run").string();
  // The bundled config with a CI-sized loop: one iteration (its five candidates, then the next
  // three when none passes, each an 800-evaluation refit). Measured 2026-12-06 with `motoflex
  // loop` on this split: the first five (torque saturation, current limit, winding heating,
  // housing temperature, encoder scale) validate worse than the M1 base (59.5 mrad); in the
  // widened round encoder offset and sensor delay do too, and load friction, ranked eighth,
  // validates at 36.0 mrad (seventh before the housing temperature was in the library, sixth
  // before the torque saturation: 2026-11-30, 211 s of refits on 2 threads). Since the released
  // joint's friction is in the library (2026-12-07) it ranks sixth there and load friction ninth.
  std::string fit =
      read_text(fs::path(MOTOFLEX_SOURCE_DIR) / "scenarios/fit/servo_pendulum_bam.yaml");
  const auto replace = [&fit](const std::string& from, const std::string& to) {
    ASSERT_NE(fit.find(from), std::string::npos) << from;
    fit.replace(fit.find(from), from.size(), to);
  };
  replace("scenario: ../", "scenario: " + std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/");
  replace("max_iterations: 6", "max_iterations: 1");
  // Five candidates, as when the widening below was measured (the bundled ten would refit load
  // friction, ninth, in the first round, and the widening would not be exercised).
  replace("candidates: 10", "candidates: 5");
  // The widened round of four (released friction, encoder offset, sensor delay, load friction)
  // rather than five: the widening is exercised and the test stays within its time limit under
  // ctest -j2 (ten refits did not, 2026-11-30; nine took 607 s beside the slow tier, 2026-12-07).
  replace("widen: 5", "widen: 4");
  std::ofstream(dir / "fit.yaml") << fit;
  // Not forced: `motoflex loop scenarios/fit/servo_pendulum_bam.yaml --data ... --validation ...`
  // must run as written, so the bundled budget has to let the base fit converge (a loop on an
  // unconverged base refuses, exit 2).
  const LoopResult result = run_loop((dir / "fit.yaml").string(), overrides, false);
  EXPECT_TRUE(result.unreliable_reason.empty()) << result.unreliable_reason;
  ASSERT_FALSE(result.iterations.empty());
  const double m1_mae = result.iterations.front().val_mae_before_rad;
  const double final_mae = result.iterations.back().val_mae_after_rad;
  std::printf("BAM XL330 validation MAE: M1 %.3f mrad -> loop %.3f mrad\n", 1e3 * m1_mae,
              1e3 * final_mae);
  EXPECT_LT(final_mae, 0.8 * m1_mae);  // 2026-11-29: 59.5 -> 36.0 mrad (one iteration)
  EXPECT_FALSE(result.final_model == result.base_model) << "the loop added nothing";
}

}  // namespace
}  // namespace motoflex::testing
