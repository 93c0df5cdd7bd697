// Effects in fit configs: one line frees an effect's parameters; bad names and effects that
// cannot apply are one-line errors naming file, line and field.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>

#include "cli/cli_test_support.hpp"
#include "effect_test_support.hpp"
#include "fit/fit_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/effects/effect_loop.hpp"
#include "motoflex/fit/fit_run.hpp"
#include "motoflex/fit/refit_config.hpp"
#include "motoflex/model/effect_library.hpp"

namespace motoflex::testing {
namespace {

bool is_free(const FitConfig& config, const std::string& name) {
  return std::any_of(
      config.free_parameters.begin(), config.free_parameters.end(), [&](const FreeParameter& p) {
        return std::find(p.targets.begin(), p.targets.end(), name) != p.targets.end();
      });
}

std::string error_of(const std::string& fit) {
  try {
    load_fit_config(fit);
  } catch (const InputError& error) {
    return error.what();
  }
  return "";
}

TEST(EffectConfig, OneLineAddsAnEffectsParameters) {
  const auto dir = fresh_dir("effect_config_add");
  const FitConfig config =
      load_fit_config(write_hidden_bench_fit(dir, "none", "{}", "effects: [stribeck]\n"));
  EXPECT_TRUE(is_free(config, "joint.pendulum.stribeck_nm"));
  EXPECT_TRUE(is_free(config, "joint.pendulum.stribeck_velocity_rad_s"));
  EXPECT_EQ(config.space->dimension(), 6u);
  EXPECT_EQ(config.effects, std::vector<std::string>{"stribeck"});
}

TEST(EffectConfig, BadEffectsAreOneLineErrors) {
  const auto dir = fresh_dir("effect_config_bad");
  const std::string unknown =
      error_of(write_hidden_bench_fit(dir, "none", "{}", "effects: [stribek]\n"));
  EXPECT_NE(unknown.find("fit.yaml:"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("unknown effect 'stribek'"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("stribeck"), std::string::npos) << unknown;
  EXPECT_EQ(std::count(unknown.begin(), unknown.end(), '\n'), 0);

  const std::string fixed = error_of(write_hidden_bench_fit(
      dir, "none", "{}", "fixed: {sensor.delay_s: 0.01}\neffects: [sensor_delay]\n"));
  EXPECT_NE(fixed.find("every parameter of effect 'sensor_delay' is fixed"), std::string::npos)
      << fixed;

  const std::string no_hook =
      error_of(write_hidden_bench_fit(dir, "none", "{}", "effects: [backlash]\n"));
  EXPECT_NE(no_hook.find("effect 'backlash' has no hook in robot servo_pendulum"),
            std::string::npos)
      << no_hook;

  const std::string loop_effect =
      error_of(write_hidden_bench_fit(dir, "none", "{effects: [gravity]}"));
  EXPECT_NE(loop_effect.find("unknown effect 'gravity'"), std::string::npos) << loop_effect;
}

TEST(EffectConfig, ResidualsNeedAFinishedFit) {
  const auto dir = fresh_dir("effect_config_unfinished");
  try {
    load_finished_fit(dir.string());
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("no finished fit here"), std::string::npos)
        << error.what();
  }
  const CommandResult result = run_motoflex("residuals " + dir.string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.stderr_text.find("no finished fit here"), std::string::npos);
}

TEST(EffectConfig, TheLoopNeedsValidationLogsOfTheSameRobot) {
  const auto dir = fresh_dir("effect_config_loop");
  const std::string fit = write_hidden_bench_fit(dir, "none", "{}");
  FitOverrides other_robot;
  other_robot.validation = std::string(MOTOFLEX_SOURCE_DIR) + "/reference_data/nao/validation";
  try {
    run_loop(fit, other_robot);
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("log of robot 'nao'"), std::string::npos)
        << error.what();
  }
  std::string text = read_text(fit);
  text.erase(text.find("validation:"),
             text.find('\n', text.find("validation:")) - text.find("validation:") + 1);
  std::ofstream(fit) << text;
  try {
    run_loop(fit, {});
    FAIL() << "no error";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("validation"), std::string::npos) << error.what();
  }
}

// A loop's refit has the model it extends (its fitted values, the new effect at its neutral value)
// as its incumbent: evaluated before the search, so the refit can never end with a worse training
// fitness than that model, even when the effect's own start (here a Stribeck peak at its upper
// bound on logs without one) and a tiny search step keep every sample far worse.
TEST(EffectConfig, ARefitNeverEndsWorseThanTheModelItExtends) {
  const auto dir = fresh_dir("effect_config_incumbent");
  const FitConfig base = load_fit_config(write_hidden_bench_fit(
      dir, "none",
      "{refit: {strategy: {kind: cma_es, sigma: 0.001, restarts: 0}, budget: {evaluations: 13}}}"));
  nlohmann::json fitted = nlohmann::json::object();
  for (const FreeParameter& p : base.free_parameters) fitted[p.name] = p.start;
  const FitSpec spec = refit_spec(base, fitted, find_effect("stribeck"),
                                  {{"joint.pendulum.stribeck_nm", 2.0}}, (dir / "refit").string());
  ASSERT_EQ(spec.incumbent.size(), spec.free.size());
  std::map<std::string, double> incumbent(spec.incumbent.begin(), spec.incumbent.end());
  EXPECT_EQ(incumbent.at("joint.pendulum.stribeck_nm"), 0.0);
  EXPECT_EQ(incumbent.at("bench.Kt_nm_per_a"), 0.5);

  // As the loop runs it: written as fit.yaml and read back.
  const FitConfig refit = load_fit_config(write_refit_config(base, fitted, find_effect("stribeck"),
                                                             {{"joint.pendulum.stribeck_nm", 2.0}},
                                                             (dir / "refit").string()));
  ASSERT_EQ(refit.incumbent_x.size(), refit.space->dimension());
  const double incumbent_fitness =
      refit.train->evaluate(refit.space->apply(refit.incumbent_x)).fitness;
  const double peak_fitness =
      refit.train->evaluate(refit.space->apply(refit.space->start())).fitness;
  ASSERT_GT(peak_fitness, 2.0 * incumbent_fitness);  // the search's own start is far worse
  const FinishedFit done = ensure_fit(refit);
  EXPECT_EQ(done.summary["best_fitness"].get<double>(), incumbent_fitness);
  EXPECT_EQ(done.best_json["free"]["joint.pendulum.stribeck_nm"].get<double>(), 0.0);
}

// `loop: {refit: {polish: ...}}` finishes every refit with it (written into the refit's fit.yaml,
// so a resumed loop polishes the same way); without it a refit has no polish.
TEST(EffectConfig, ARefitTakesTheLoopsPolish) {
  const auto dir = fresh_dir("effect_config_refit_polish");
  const FitConfig plain = load_fit_config(write_hidden_bench_fit(dir, "none", "{}"));
  const FitConfig polished = load_fit_config(write_hidden_bench_fit(
      dir, "none", "{refit: {polish: {method: lm, max_iterations: 3, covariance: false}}}"));
  const nlohmann::json fitted = nlohmann::json::object();
  const FitConfig a = load_fit_config(
      write_refit_config(plain, fitted, find_effect("stribeck"), {}, (dir / "plain").string()));
  const FitConfig b = load_fit_config(write_refit_config(polished, fitted, find_effect("stribeck"),
                                                         {}, (dir / "polished").string()));
  EXPECT_FALSE(a.polish.lm());
  EXPECT_TRUE(b.polish.lm());
  EXPECT_EQ(b.polish.max_iterations, 3u);
  EXPECT_FALSE(b.polish.covariance);
}

// When the loop's start for a refit is already better than the current model, the start is the
// incumbent: a search that samples only around its start can then never end above it.
TEST(EffectConfig, AStartBetterThanTheModelIsTheIncumbent) {
  const auto dir = fresh_dir("effect_config_start_incumbent");
  const FitConfig base = load_fit_config(write_hidden_bench_fit(dir, "none", "{}"));
  nlohmann::json fitted = nlohmann::json::object();
  for (const FreeParameter& p : base.free_parameters) fitted[p.name] = p.start;
  nlohmann::json start = fitted;
  start["bench.Kt_nm_per_a"] = 0.4;
  const Effect& stribeck = find_effect("stribeck");
  const FitSpec kept = refit_spec(base, fitted, stribeck, {{"joint.pendulum.stribeck_nm", 0.1}},
                                  (dir / "a").string(), start);
  const FitSpec moved = refit_spec(base, fitted, stribeck, {{"joint.pendulum.stribeck_nm", 0.1}},
                                   (dir / "b").string(), start, true);
  const std::map<std::string, double> a(kept.incumbent.begin(), kept.incumbent.end());
  const std::map<std::string, double> b(moved.incumbent.begin(), moved.incumbent.end());
  EXPECT_EQ(a.at("bench.Kt_nm_per_a"), 0.5);  // the current model, effect neutral
  EXPECT_EQ(a.at("joint.pendulum.stribeck_nm"), 0.0);
  EXPECT_EQ(b.at("bench.Kt_nm_per_a"), 0.4);  // the start
  EXPECT_EQ(b.at("joint.pendulum.stribeck_nm"), 0.1);
}

// `loop: {refit: {scan: N}}`: read, kept through a refit's fit.yaml, and 1 or 2 points (no span
// to scan) rejected naming the field.
TEST(EffectConfig, RefitScanIsReadAndChecked) {
  const auto dir = fresh_dir("effect_config_refit_scan");
  const FitConfig scanned =
      load_fit_config(write_hidden_bench_fit(dir / "nine", "none", "{refit: {scan: 9}}"));
  EXPECT_EQ(scanned.loop.refit_scan, 9u);
  EXPECT_EQ(load_fit_config(write_hidden_bench_fit(dir / "none", "none", "{}")).loop.refit_scan,
            0u);
  try {
    load_fit_config(write_hidden_bench_fit(dir / "two", "none", "{refit: {scan: 2}}"));
    FAIL() << "scan: 2 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scan"), std::string::npos) << e.what();
  }
  // scan_pairs: off unless asked for, written back into a refit's fit.yaml only when on (an
  // older loop's identity is unchanged), and refused without the scan it refines.
  EXPECT_FALSE(scanned.loop.refit_scan_pairs);
  EXPECT_FALSE(fit_spec_to_json(scanned)["loop"]["refit"].contains("scan_pairs"));
  const FitConfig paired = load_fit_config(
      write_hidden_bench_fit(dir / "pairs", "none", "{refit: {scan: 9, scan_pairs: true}}"));
  EXPECT_TRUE(paired.loop.refit_scan_pairs);
  EXPECT_EQ(fit_spec_to_json(paired)["loop"]["refit"]["scan_pairs"], true);
  try {
    load_fit_config(
        write_hidden_bench_fit(dir / "pairs_alone", "none", "{refit: {scan_pairs: true}}"));
    FAIL() << "scan_pairs without scan accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("scan_pairs"), std::string::npos) << e.what();
  }
}

// evaluation_spec: the loop's carry-over of re-optimised values to a model without the refit's
// effect is a fit of the model's own parameters that evaluates exactly those values once.
TEST(EffectConfig, AnEvaluationSpecScoresExactlyTheGivenValuesOnce) {
  const auto dir = fresh_dir("effect_config_evaluation");
  const FitConfig base = load_fit_config(write_hidden_bench_fit(dir, "none", "{}"));
  nlohmann::json fitted = nlohmann::json::object();
  for (const FreeParameter& p : base.free_parameters) fitted[p.name] = 0.5 * (p.lower + p.upper);
  fitted["joint.pendulum.stribeck_nm"] = 0.1;  // an effect's parameter: not part of the model
  const FitSpec spec = evaluation_spec(base, fitted, (dir / "evaluation").string());
  std::filesystem::create_directories(dir / "evaluation");
  std::ofstream(dir / "evaluation" / "fit.yaml") << fit_spec_to_json(spec).dump(2) << "\n";
  const FitConfig config = load_fit_config((dir / "evaluation" / "fit.yaml").string());
  ASSERT_EQ(config.free_parameters.size(), base.free_parameters.size());
  EXPECT_EQ(config.name, base.name);
  const FinishedFit fit = ensure_fit(config);
  EXPECT_EQ(fit.summary.value("evaluations", 0), 1);
  ParameterSet expected = config.space->base();
  for (const FreeParameter& p : base.free_parameters) {
    EXPECT_EQ(fit.best_json["free"][p.name].get<double>(), fitted[p.name].get<double>()) << p.name;
    expected.set(p.name, fitted[p.name].get<double>());
  }
  EXPECT_EQ(fit.best.get("joint.pendulum.stribeck_nm"), 0.0);
  EXPECT_EQ(fit.summary.value("best_fitness", 0.0), config.train->evaluate(expected).fitness);
}

// `loop: {control: ...}`: on unless switched off, kept when the spec is written back (the loop's
// identity hashes it), and a value that is not a boolean rejected naming the field.
TEST(EffectConfig, ControlRefitIsOnByDefaultAndRead) {
  const auto dir = fresh_dir("effect_config_control");
  const FitConfig on = load_fit_config(write_hidden_bench_fit(dir / "on", "none", "{}"));
  const FitConfig off =
      load_fit_config(write_hidden_bench_fit(dir / "off", "none", "{control: false}"));
  EXPECT_TRUE(on.loop.control);
  EXPECT_FALSE(off.loop.control);
  EXPECT_EQ(fit_spec_to_json(off)["loop"]["control"], false);
  EXPECT_EQ(fit_spec_to_json(on)["loop"]["control"], true);
  try {
    load_fit_config(write_hidden_bench_fit(dir / "bad", "none", "{control: 3}"));
    FAIL() << "control: 3 accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("control"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace motoflex::testing
