// The least-squares finish (`polish: {method: lm}`) and the parameter uncertainty: the
// covariance σ²(JᵀJ)⁻¹ against a hand computation on a straight-line fit, and on the pendulum
// bench with logs recorded from a known truth (plus white encoder noise), LM from a nearby start
// recovers the truth and its 95 % intervals cover it.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "fit_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/fit/parameter_covariance.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;
using testing::pendulum_truth;
using testing::read_text;
using testing::record_pendulum_log;

TEST(FitLmPolishTest, CovarianceOfAStraightLineFitIsSigmaSquaredTimesTheInverseNormalMatrix) {
  // y = a + b·t at t = 0, 1, 2, 3: J = [1 t], JᵀJ = [[4, 6], [6, 14]], det 20,
  // (JᵀJ)⁻¹ = [[14, −6], [−6, 4]] / 20; RSS 0.8 over N − p = 2 gives σ² = 0.4.
  const std::vector<double> j = {1, 0, 1, 1, 1, 2, 1, 3};
  const LeastSquaresCovariance c = least_squares_covariance(j, 4, 2, 0.8, 1.0);
  EXPECT_DOUBLE_EQ(c.sigma2, 0.4);
  EXPECT_EQ(c.rank, 2u);
  EXPECT_NEAR(c.covariance[0][0], 0.4 * 14.0 / 20.0, 1e-14);
  EXPECT_NEAR(c.covariance[0][1], -0.4 * 6.0 / 20.0, 1e-14);
  EXPECT_NEAR(c.covariance[1][0], -0.4 * 6.0 / 20.0, 1e-14);
  EXPECT_NEAR(c.covariance[1][1], 0.4 * 4.0 / 20.0, 1e-14);
  EXPECT_NEAR(c.standard_error[1], std::sqrt(0.08), 1e-14);
  EXPECT_NEAR(c.correlation[0][1], -6.0 / std::sqrt(14.0 * 4.0), 1e-12);
  EXPECT_NEAR(c.correlation[0][0], 1.0, 1e-12);
}

TEST(FitLmPolishTest, ADirectionTheDataCannotSeeHasNoFiniteVariance) {
  // Columns 0 and 1 are equal (only their sum is determined); column 2 is independent.
  const std::vector<double> j = {1, 1, 0, 2, 2, 1, 3, 3, 0, 1, 1, 5};
  const LeastSquaresCovariance c = least_squares_covariance(j, 4, 3, 1.0, 1.0);
  EXPECT_EQ(c.rank, 2u);
  EXPECT_TRUE(std::isinf(c.standard_error[0]));
  EXPECT_TRUE(std::isinf(c.standard_error[1]));
  EXPECT_TRUE(std::isfinite(c.standard_error[2]));
  EXPECT_THROW(least_squares_covariance(j, 4, 4, 1.0, 1.0), std::invalid_argument);
}

// A fit of the four bench parameters from 15 % off the truth, the strategy given almost no
// budget, so that LM does the work.
// `friction` replaces the friction's range and start ("" keeps 0.001..0.5 from 15 % off).
std::string write_fit(const fs::path& dir, const fs::path& data, const std::string& polish,
                      const std::string& budget = "{evaluations: 16}",
                      const std::string& friction = "") {
  const auto truth = pendulum_truth();
  const auto start = [&](const char* name) { return std::to_string(1.15 * truth.at(name)); };
  const std::string friction_range =
      friction.empty()
          ? "lower: 0.001, upper: 0.5, log: true, start: " + start("joint.pendulum.friction_nm")
          : friction;
  const std::string path = (dir / "fit.yaml").string();
  std::ofstream(path) << "name: lm\nscenario: " << testing::kPendulumScenario << "\n"
                      << "data: " << data.string() << "\nfree:\n"
                      << "  bench.Kt_nm_per_a: {lower: 0.1, upper: 3.0, log: true, start: "
                      << start("bench.Kt_nm_per_a") << "}\n"
                      << "  joint.pendulum.friction_nm: {" << friction_range << "}\n"
                      << "  joint.pendulum.viscous_nm_s_per_rad: {lower: 0.001, upper: 1.0, "
                      << "log: true, start: " << start("joint.pendulum.viscous_nm_s_per_rad")
                      << "}\n"
                      << "  bench.armature_kg_m2: {lower: 0.0001, upper: 0.05, log: true, start: "
                      << start("bench.armature_kg_m2") << "}\n"
                      << "strategy: {kind: cma_es, sigma: 0.001, restarts: 0}\n"
                      << "budget: " << budget << "\nthreads: 2\nseed: 3\n"
                      << polish;
  return path;
}

TEST(FitLmPolishTest, LmRecoversTheTruthAndItsIntervalsCoverIt) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_lm_polish");
  fs::remove_all(dir);
  // White encoder noise of 1 mrad (seeded) on the "measured" angles.
  record_pendulum_log(dir / "data", "noisy", {{"sensor.noise_rad", 1e-3}}, 5);
  FitOverrides overrides;
  overrides.out = (dir / "run").string();
  const FitSummary summary =
      FitSession(load_fit_config(
                     write_fit(dir, dir / "data", "polish: {method: lm, max_iterations: 30}\n"),
                     overrides),
                 false)
          .run();
  const nlohmann::json json = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  ASSERT_TRUE(json.contains("polish"));
  EXPECT_TRUE(json["polish"]["used"].get<bool>());
  std::printf("[ lm       ] fitness %.6g -> %.6g in %d iterations, %llu evaluations (%s)\n",
              json["polish"]["fitness_before"].get<double>(),
              json["polish"]["fitness_after"].get<double>(),
              json["polish"]["iterations"].get<int>(),
              static_cast<unsigned long long>(json["polish"]["evaluations"].get<std::uint64_t>()),
              json["polish"]["termination"].get<std::string>().c_str());
  ASSERT_TRUE(json.contains("confidence_intervals"));
  ASSERT_TRUE(json.contains("correlation"));
  int covered = 0, compared = 0;
  for (const auto& [name, truth] : pendulum_truth()) {
    if (!json["free"].contains(name)) continue;  // R is not free
    const double value = json["free"][name].get<double>();
    const auto& ci = json["confidence_intervals"][name];
    const double lower = ci["lower"].get<double>(), upper = ci["upper"].get<double>();
    std::printf("[ lm       ] %-38s truth %.6g fitted %.6g (%+.3f %%) 95 %% [%.6g, %.6g]\n",
                name.c_str(), truth, value, 100.0 * (value / truth - 1.0), lower, upper);
    // From 15 % off to within 1 % (measured: within 0.46 %).
    EXPECT_NEAR(value, truth, 0.01 * truth) << name;
    // The 95 % interval: its half-width against the error (measured |error| / half-width:
    // K_t 0.64, armature 0.22, friction 1.14, viscous 0.42 — four 95 % intervals all cover the
    // truth only 81 % of the time, so one may miss it by a little, none by far).
    const double half_width = 0.5 * (upper - lower);
    EXPECT_LT(std::abs(value - truth), 1.5 * half_width) << name;
    covered += lower <= truth && truth <= upper ? 1 : 0;
    ++compared;
    EXPECT_TRUE(ci["identified"].get<bool>()) << name;
    // The bench's residual is smooth in every parameter at the Jacobian's step.
    std::printf("[ lm       ] %-38s nonlinearity %.4f\n", name.c_str(),
                ci["nonlinearity"].get<double>());
    EXPECT_LT(ci["nonlinearity"].get<double>(), FittedParameter::kNonlinearShare) << name;
  }
  EXPECT_EQ(compared, 4);
  EXPECT_GE(covered, compared - 1);  // measured 3 of 4
  // The report prints the intervals.
  EXPECT_NE(summary.full_report().find("95 % interval"), std::string::npos);
  EXPECT_NE(summary.brief_report().find("0 of 4 parameters unidentified"), std::string::npos);
  fs::remove_all(dir);
}

// `jacobian: forward` spends p rollout sets on a Jacobian instead of central differences' 2p:
// on the same noisy logs and from the same start LM still recovers the truth to 1 %, and no
// iteration costs more than p + 1 rollout sets (a Jacobian and the point itself; a rejected
// step costs one), where central differences need up to 2p + 1.
TEST(FitLmPolishTest, ForwardDifferencesRecoverTheTruthWithHalfTheRolloutsPerJacobian) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_lm_forward");
  fs::remove_all(dir);
  record_pendulum_log(dir / "data", "noisy", {{"sensor.noise_rad", 1e-3}}, 5);
  std::map<std::string, nlohmann::json> polish;
  for (const std::string scheme : {"central", "forward"}) {
    FitOverrides overrides;
    overrides.out = (dir / scheme).string();
    FitSession(
        load_fit_config(
            write_fit(dir, dir / "data",
                      "polish: {method: lm, max_iterations: 30, jacobian: " + scheme + "}\n"),
            overrides),
        false)
        .run();
    const nlohmann::json json = nlohmann::json::parse(read_text(dir / scheme / "summary.json"));
    polish[scheme] = json["polish"];
    std::printf(
        "[ lm       ] %s: fitness %.6g -> %.6g in %d iterations, %llu evaluations\n",
        scheme.c_str(), json["polish"]["fitness_before"].get<double>(),
        json["polish"]["fitness_after"].get<double>(), json["polish"]["iterations"].get<int>(),
        static_cast<unsigned long long>(json["polish"]["evaluations"].get<std::uint64_t>()));
    ASSERT_TRUE(json["polish"]["used"].get<bool>()) << scheme;
    int compared = 0;
    for (const auto& [name, truth] : pendulum_truth()) {
      if (!json["free"].contains(name)) continue;
      EXPECT_NEAR(json["free"][name].get<double>(), truth, 0.01 * truth) << scheme << " " << name;
      ++compared;
    }
    EXPECT_EQ(compared, 4);
  }
  const auto cost_bound = [&](const std::string& scheme, std::uint64_t per_iteration) {
    return per_iteration * static_cast<std::uint64_t>(polish[scheme]["iterations"].get<int>() + 1);
  };
  const std::uint64_t p = 4;
  EXPECT_LE(polish["forward"]["evaluations"].get<std::uint64_t>(), cost_bound("forward", p + 1));
  // Central differences do cost more than forward ones could: the bound above is not slack.
  EXPECT_GT(polish["central"]["evaluations"].get<std::uint64_t>(), cost_bound("central", p + 1));
  fs::remove_all(dir);
}

// LM's iterations are what a long polish spends its time on (each: 2p passes over the logs):
// the console gets one line per iteration with a fitness that never rises, a cancel ends the
// polish after the iteration in which it came, and a spent time budget leaves LM out.
TEST(FitLmPolishTest, LmReportsEachIterationAndStopsWhenCancelled) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_lm_progress");
  fs::remove_all(dir);
  record_pendulum_log(dir / "data", "noisy", {{"sensor.noise_rad", 1e-3}}, 5);
  const std::string polish = "polish: {method: lm, max_iterations: 30, covariance: false}\n";
  const auto lm_iterations = [](const std::vector<FitProgress>& events) {
    std::vector<FitProgress> out;
    for (const FitProgress& e : events) {
      if (e.polish && e.polish_algorithm.rfind("lm iteration ", 0) == 0) out.push_back(e);
    }
    return out;
  };

  FitOverrides overrides;
  overrides.out = (dir / "full").string();
  FitSession full(load_fit_config(write_fit(dir, dir / "data", polish), overrides), false);
  std::vector<FitProgress> events;
  full.set_progress([&](const FitProgress& e) { events.push_back(e); });
  full.run();
  const nlohmann::json json = nlohmann::json::parse(read_text(dir / "full" / "summary.json"));
  const int iterations = json["polish"]["iterations"].get<int>();
  const std::vector<FitProgress> steps = lm_iterations(events);
  ASSERT_EQ(steps.size(), static_cast<std::size_t>(iterations));
  ASSERT_GE(iterations, 3);  // measured 4 from 15 % off the truth: a cancel at 1 cuts it short
  for (std::size_t k = 0; k < steps.size(); ++k) {
    EXPECT_EQ(steps[k].polish_algorithm, "lm iteration " + std::to_string(k));
    if (k > 0) {
      EXPECT_LE(steps[k].best_fitness, steps[k - 1].best_fitness);
      EXPECT_GT(steps[k].evaluations, steps[k - 1].evaluations);
    }
  }
  // Iteration 0 is the strategy's best point; LM's last is where the polish ended.
  EXPECT_NEAR(steps.front().best_fitness, json["polish"]["fitness_before"].get<double>(),
              1e-9 * steps.front().best_fitness);
  EXPECT_LT(steps.back().best_fitness, 0.5 * steps.front().best_fitness);

  overrides.out = (dir / "cancelled").string();
  FitSession cancelled(load_fit_config(write_fit(dir, dir / "data", polish), overrides), false);
  cancelled.set_progress([&](const FitProgress& e) {
    if (e.polish_algorithm == "lm iteration 1") cancelled.cancel();
  });
  cancelled.run();
  const nlohmann::json stopped =
      nlohmann::json::parse(read_text(dir / "cancelled" / "summary.json"));
  EXPECT_EQ(stopped["polish"]["iterations"].get<int>(), 2);  // iterations 0 and 1
  EXPECT_EQ(stopped["stop_reason"], "interrupted");

  overrides.out = (dir / "no_time").string();
  FitSession(
      load_fit_config(write_fit(dir, dir / "data", polish, "{evaluations: 16, seconds: 1.0e-9}"),
                      overrides),
      false)
      .run();
  const nlohmann::json no_time = nlohmann::json::parse(read_text(dir / "no_time" / "summary.json"));
  EXPECT_EQ(no_time["polish"]["termination"], "not run: the time budget was spent");
  EXPECT_FALSE(no_time["polish"]["used"].get<bool>());
  fs::remove_all(dir);
}

TEST(FitLmPolishTest, ThePolishSectionIsCheckedAndRoundTrips) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_lm_spec");
  fs::remove_all(dir);
  fs::create_directories(dir);
  EXPECT_THROW(load_fit_spec(write_fit(dir, dir, "polish: {method: gauss}\n")), InputError);
  EXPECT_THROW(load_fit_spec(write_fit(dir, dir, "polish: {max_iterations: 0}\n")), InputError);
  EXPECT_THROW(load_fit_spec(write_fit(dir, dir, "polish: {jacobian_step: 0.5}\n")), InputError);
  EXPECT_THROW(load_fit_spec(write_fit(dir, dir, "polish: {jacobian: backward}\n")), InputError);
  EXPECT_THROW(load_fit_spec(write_fit(dir, dir, "polish: {method: none, jacobian: forward}\n")),
               InputError);
  const FitSpec forward = load_fit_spec(write_fit(dir, dir, "polish: {jacobian: forward}\n"));
  EXPECT_EQ(forward.polish.lm_jacobian, FiniteDifferences::kForward);
  EXPECT_EQ(fit_spec_to_json(forward)["polish"]["jacobian"], "forward");
  const FitSpec spec =
      load_fit_spec(write_fit(dir, dir, "polish: {max_iterations: 7, covariance: false}\n"));
  EXPECT_TRUE(spec.polish.lm());  // method defaults to lm inside the section
  EXPECT_EQ(spec.polish.max_iterations, 7u);
  EXPECT_FALSE(spec.polish.reports_uncertainty());
  const auto json = fit_spec_to_json(spec);
  EXPECT_EQ(json["polish"]["method"], "lm");
  EXPECT_EQ(json["polish"]["max_iterations"], 7);
  EXPECT_FALSE(fit_spec_to_json(load_fit_spec(write_fit(dir, dir, ""))).contains("polish"));
  // The flat-direction scan needs at least three points and LM.
  EXPECT_THROW(load_fit_spec(write_fit(dir, dir, "polish: {flat_scan: 2}\n")), InputError);
  EXPECT_THROW(load_fit_spec(write_fit(dir, dir, "polish: {method: none, flat_scan: 5}\n")),
               InputError);
  const FitSpec scanned = load_fit_spec(write_fit(dir, dir, "polish: {flat_scan: 5}\n"));
  EXPECT_EQ(scanned.polish.flat_scan, 5u);
  EXPECT_EQ(fit_spec_to_json(scanned)["polish"]["flat_scan"], 5);
  EXPECT_FALSE(fit_spec_to_json(spec)["polish"].contains("flat_scan"));  // hashes unchanged
  EXPECT_FALSE(fit_spec_to_json(spec)["polish"].contains("jacobian"));
  fs::remove_all(dir);
}

// A dry friction far above what the servo can push through locks the joint: no small change of
// it changes a rollout, its Jacobian column is zero and LM cannot move it. The flat-direction
// scan tries it across its bounds, finds where the joint moves again, and LM goes on from there
// to the truth. The strategy is given almost no budget (16 evaluations at σ = 0.001), so the
// start is what LM gets.
TEST(FitLmPolishTest, AFlatScanFreesALockedFrictionThatLmAloneCannotMove) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_lm_flat_scan");
  fs::remove_all(dir);
  record_pendulum_log(dir / "data", "clean");
  const std::string locked = "lower: 0.001, upper: 50.0, log: true, start: 50.0";
  const auto fit = [&](const std::string& name, const std::string& polish) {
    FitOverrides overrides;
    overrides.out = (dir / name).string();
    FitSession(load_fit_config(write_fit(dir, dir / "data", polish, "{evaluations: 16}", locked),
                               overrides),
               false)
        .run();
    return nlohmann::json::parse(read_text(dir / name / "summary.json"));
  };
  const std::string name = "joint.pendulum.friction_nm";
  const double truth = pendulum_truth().at(name);
  const nlohmann::json alone = fit("alone", "polish: {method: lm, max_iterations: 30}\n");
  const nlohmann::json scanned =
      fit("scanned", "polish: {method: lm, max_iterations: 30, flat_scan: 9}\n");
  std::printf("[ flat     ] LM alone: friction %.6g N m, F %.6g; with the scan: %.6g N m, F %.6g\n",
              alone["free"][name].get<double>(), alone["polish"]["fitness_after"].get<double>(),
              scanned["free"][name].get<double>(),
              scanned["polish"]["fitness_after"].get<double>());
  // LM alone leaves the friction where it locks the joint.
  EXPECT_GT(alone["free"][name].get<double>(), 10.0 * truth);
  // The scan moves it, and LM then takes every parameter to within 1 % of the truth.
  ASSERT_TRUE(scanned["polish"].contains("flat_scan_moves"));
  EXPECT_GE(scanned["polish"]["flat_scan_moves"].size(), 1u);
  for (const auto& [parameter, value] : pendulum_truth()) {
    if (!scanned["free"].contains(parameter)) continue;
    EXPECT_NEAR(scanned["free"][parameter].get<double>(), value, 0.01 * value) << parameter;
  }
  EXPECT_LT(scanned["polish"]["fitness_after"].get<double>(),
            1e-3 * alone["polish"]["fitness_after"].get<double>());
  fs::remove_all(dir);
}

TEST(FitLmPolishTest, WithoutPolishTheSummaryHasNoIntervals) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_lm_nopolish");
  fs::remove_all(dir);
  record_pendulum_log(dir / "data", "clean");
  FitOverrides overrides;
  overrides.out = (dir / "run").string();
  FitSession(load_fit_config(write_fit(dir, dir / "data", ""), overrides), false).run();
  const nlohmann::json json = nlohmann::json::parse(read_text(dir / "run" / "summary.json"));
  EXPECT_FALSE(json.contains("polish"));
  EXPECT_FALSE(json.contains("confidence_intervals"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motoflex
