// `motoflex residuals` on a fit of logs with a hidden sensor delay (15 ms, written only in
// scenarios/truth/hidden/sensor_delay.yaml): what the command writes is checked against the fit
// it analyses and against the delay it should find.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "cli/cli_test_support.hpp"

namespace motoflex::testing {
namespace {

namespace fs = std::filesystem;

const std::string kSource = MOTOFLEX_SOURCE_DIR;

nlohmann::json read_json(const fs::path& path) {
  std::ifstream in(path);
  return nlohmann::json::parse(in);
}

std::size_t data_rows(const fs::path& csv) {
  std::ifstream in(csv);
  std::string line;
  std::size_t rows = 0;
  std::getline(in, line);  // header
  while (std::getline(in, line)) rows += line.empty() ? 0 : 1;
  return rows;
}

TEST(ResidualsCli, FindsTheHiddenDelayAndMatchesTheFitItAnalyses) {
  const fs::path dir = fresh_dir("residuals_cli");
  const fs::path run = dir / "fit";
  const CommandResult fit = run_motoflex(
      "fit " + kSource + "/scenarios/fit/bench_hidden.yaml --data " + kSource +
      "/reference_data/hidden/sensor_delay/train --validation " + kSource +
      "/reference_data/hidden/sensor_delay/validation --max-evaluations 160 --out " + run.string());
  ASSERT_EQ(fit.exit_code, 0) << fit.stderr_text;
  // 160 evaluations end the fit before it converges: residuals needs --force, and says so.
  const CommandResult refused = run_motoflex("residuals " + run.string());
  EXPECT_EQ(refused.exit_code, 2) << refused.stdout_text;
  const CommandResult residuals = run_motoflex("residuals " + run.string() + " --force");
  ASSERT_EQ(residuals.exit_code, 0) << residuals.stderr_text;

  const nlohmann::json analysis = read_json(run / "residuals" / "residuals.json");
  const nlohmann::json summary = read_json(run / "summary.json");
  EXPECT_FALSE(summary["converged"].get<bool>());
  EXPECT_FALSE(analysis["ranking_reliable"].get<bool>());
  // The analysis simulates the fit's best parameters: its training RMS is the fit's.
  EXPECT_NEAR(analysis["train"]["rms_deg"].get<double>(),
              summary["rms_deg"]["overall"].get<double>(), 1e-9);
  EXPECT_NEAR(analysis["validation"]["rms_deg"].get<double>(),
              summary["validation"]["rms_deg"]["overall"].get<double>(), 1e-9);
  // A delay leaves −(joint velocity)·delay in the residual: at lag 0 it correlates negatively
  // with the command velocity (measured −0.49; the fit's armature and viscous terms absorb part
  // of the lag, so the residual's own best lag stays at 0).
  const nlohmann::json& joint = analysis["train"]["joints"][0];
  const std::size_t zero_lag = joint["lag_s"].size() / 2;
  ASSERT_NEAR(joint["lag_s"][zero_lag].get<double>(), 0.0, 1e-12);
  EXPECT_LT(joint["lag_correlation_with_command_velocity"][zero_lag].get<double>(), -0.3);
  // The ranking puts the sensor delay first, in the JSON and in what the command prints.
  ASSERT_FALSE(analysis["ranking"].empty());
  EXPECT_EQ(analysis["ranking"][0]["effect"], "sensor_delay") << analysis["ranking"].dump(1);
  EXPECT_NE(residuals.stdout_text.find("1. sensor_delay"), std::string::npos)
      << residuals.stdout_text;
  // One series row per scored frame of the training logs.
  std::size_t frames = 0;
  for (const auto& robot : summary["robots"]) frames += robot["frames"].get<std::size_t>();
  EXPECT_EQ(data_rows(run / "residuals" / "train_series.csv"), frames);
  // The Markdown report names the effect in its ranking table.
  std::ifstream md(run / "residuals" / "residuals.md");
  const std::string text{std::istreambuf_iterator<char>(md), std::istreambuf_iterator<char>()};
  EXPECT_NE(text.find("## Candidate effects"), std::string::npos);
  EXPECT_NE(text.find("sensor_delay"), std::string::npos);
}

}  // namespace
}  // namespace motoflex::testing
