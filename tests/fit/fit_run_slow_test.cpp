// motoflex fit end to end on the pendulum bench: parameter recovery, determinism across
// thread counts, exact resume, early termination that changes no selection.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"
#include "fit_test_support.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_problem.hpp"
#include "motoflex/fit/fit_session.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const char* kSmallEs = "{kind: mu_plus_lambda, mu: 4, lambda: 12, kappa: 3}";

nlohmann::json read_json(const fs::path& path) {
  return nlohmann::json::parse(read_text(path));
}

TEST(FitRun, RecoversTheTruthFromNoiseFreeLogs) {
  const fs::path dir = fresh_dir("fit_recover");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit =
      write_pendulum_fit(dir, dir / "data", "{kind: cma_es, sigma: 0.3}", "{evaluations: 1200}",
                         "out: " + (dir / "run").string() + "\n");
  FitSession(load_fit_config(fit), false).run();
  const nlohmann::json best = read_json(dir / "run" / "best.json");
  // With R fixed at its truth, K_t (through K_t/R), the viscous term (through K_t²/R + K_v),
  // the Coulomb friction and the armature are all identifiable.
  for (const auto& [name, truth] : pendulum_truth()) {
    if (name == "bench.R_ohm") continue;
    EXPECT_NEAR(best["free"][name].get<double>(), truth, 0.05 * truth) << name;
  }
}

TEST(FitRun, NoisyLogsReachTheNoiseFloor) {
  const fs::path dir = fresh_dir("fit_noise");
  const double noise_rad = 0.002;
  record_pendulum_log(dir / "data", "sin_sin", {{"sensor.noise_rad", noise_rad}});
  const std::string fit =
      write_pendulum_fit(dir, dir / "data", "{kind: cma_es, sigma: 0.3}", "{evaluations: 800}",
                         "out: " + (dir / "run").string() + "\n");
  FitSession(load_fit_config(fit), false).run();
  const nlohmann::json summary = read_json(dir / "run" / "summary.json");
  const double rms_rad = summary["rms_deg"]["overall"].get<double>() * M_PI / 180.0;
  EXPECT_LT(rms_rad, 1.1 * noise_rad);
  EXPECT_GT(rms_rad, 0.8 * noise_rad);  // it cannot fit the noise itself
}

TEST(FitRun, OneAndTwoThreadsGiveIdenticalRuns) {
  const fs::path dir = fresh_dir("fit_threads");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 6}");
  expect_one_and_two_threads_identical(fit, dir);
}

TEST(FitRun, ResumedRunEqualsAnUninterruptedOne) {
  const fs::path dir = fresh_dir("fit_resume");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string fit = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 8}");
  FitOverrides whole, part;
  whole.out = (dir / "whole").string();
  part.out = (dir / "part").string();
  part.max_generations = 3;
  FitSession(load_fit_config(fit, whole), false).run();
  FitSession(load_fit_config(fit, part), false).run();
  FitOverrides rest = part;
  rest.max_generations = 8;
  FitSession(load_fit_config(fit, rest), true).run();
  EXPECT_EQ(generations_without_seconds(dir / "whole"), generations_without_seconds(dir / "part"));
  EXPECT_EQ(best_without_date(dir / "whole"), best_without_date(dir / "part"));
}

TEST(FitRun, EarlyTerminationChangesNoSelection) {
  const fs::path dir = fresh_dir("fit_early");
  record_pendulum_log(dir / "data", "sin_sin");
  const std::string with = write_pendulum_fit(dir, dir / "data", kSmallEs, "{generations: 8}");
  FitOverrides a, b;
  a.out = (dir / "early").string();
  b.out = (dir / "full").string();
  FitConfig early = load_fit_config(with, a);
  FitConfig full = load_fit_config(with, b);
  full.early_termination = false;
  FitSession(early, false).run();
  FitSession(full, false).run();
  // Same best point and the same best-so-far every generation; only the medians (of individuals
  // that were stopped early) may differ.
  EXPECT_EQ(best_without_date(dir / "early"), best_without_date(dir / "full"));
  auto best_column = [](const fs::path& run) {
    std::ifstream in(run / "generations.csv");
    std::string line, out;
    while (std::getline(in, line)) {
      const auto first = line.find(',');
      const auto second = line.find(',', first + 1);
      const auto third = line.find(',', second + 1);
      out += line.substr(0, third) + "\n";
    }
    return out;
  };
  EXPECT_EQ(best_column(dir / "early"), best_column(dir / "full"));
  const nlohmann::json summary = read_json(dir / "early" / "summary.json");
  EXPECT_GT(summary["early_termination"]["individuals_stopped_early"].get<int>(), 0);
  EXPECT_GT(summary["early_termination"]["frames_saved"].get<int>(), 0);
}

}  // namespace
}  // namespace motoflex::testing
