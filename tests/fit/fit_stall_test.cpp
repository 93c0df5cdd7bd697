// budget.stall_evaluations: a fit that cannot improve on its incumbent (a refit started at the
// current model with a wide CMA-ES) stops one window after the last real improvement instead of
// spending its whole budget, says so, and a run killed before the stall resumes to the same
// generations and best point.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "fit_test_support.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;
using testing::best_without_date;
using testing::first_pendulum_fit;
using testing::generations_without_seconds;
using testing::read_text;
using testing::write_pendulum_fit;

constexpr const char* kWide = "{kind: cma_es, sigma: 0.5, restarts: 0}";
constexpr const char* kStallBudget =
    "{evaluations: 3000, stall_evaluations: 60, stall_relative: 0.01}";

// The evaluation count of the last generations.csv row.
std::uint64_t last_row_evaluations(const fs::path& run) {
  std::ifstream in(run / "generations.csv");
  std::string line, last;
  while (std::getline(in, line)) last = line;
  std::stringstream row(last);
  std::string generation, evaluations;
  std::getline(row, generation, ',');
  std::getline(row, evaluations, ',');
  return std::stoull(evaluations);
}

TEST(FitStallTest, ARefitThatCannotBeatItsIncumbentStopsOneWindowAfterTheLastImprovement) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_stall");
  fs::remove_all(dir);
  const std::string best = first_pendulum_fit(dir, 120).string();
  const double first_fitness = nlohmann::json::parse(read_text(best))["fitness"].get<double>();

  fs::create_directories(dir / "refit");
  const std::string refit_yaml =
      write_pendulum_fit(dir / "refit", dir / "data", kWide, kStallBudget);
  FitOverrides whole;
  whole.out = (dir / "refit" / "whole").string();
  whole.start_from = best;
  const FitSummary summary = FitSession(load_fit_config(refit_yaml, whole), false).run();
  EXPECT_NE(summary.stop_reason.find("stall_evaluations"), std::string::npos)
      << summary.stop_reason;
  EXPECT_TRUE(summary.converged);
  EXPECT_NE(summary.convergence.find("stall"), std::string::npos);
  EXPECT_LE(summary.best_fitness, first_fitness);

  // It stopped in the first generation that reached anchor + 60 evaluations.
  const nlohmann::json checkpoint =
      nlohmann::json::parse(read_text(dir / "refit" / "whole" / "checkpoint.json"));
  const auto& extra = checkpoint["payload"]["extra"];
  ASSERT_TRUE(extra.contains("stall_anchor_evaluations")) << extra.dump();
  const std::uint64_t anchor = extra["stall_anchor_evaluations"].get<std::uint64_t>();
  const std::uint64_t stopped = last_row_evaluations(dir / "refit" / "whole");
  const std::uint64_t lambda = 4 + 4;  // CMA-ES's default 4 + ⌊3 ln 4⌋ for the 4 free parameters
  EXPECT_GE(stopped, anchor + 60);
  EXPECT_LT(stopped, anchor + 60 + lambda);
  EXPECT_LT(stopped, 3000u);
  EXPECT_TRUE(extra["main_done"].get<bool>());

  // Killed (here: a budget) before the stall, then resumed: the same run.
  FitOverrides part = whole;
  part.out = (dir / "refit" / "part").string();
  part.max_evaluations = anchor + 20;
  FitSession(load_fit_config(refit_yaml, part), false).run();
  FitOverrides rest = part;
  rest.max_evaluations = 3000;
  FitSession(load_fit_config(refit_yaml, rest), true).run();
  EXPECT_EQ(generations_without_seconds(dir / "refit" / "whole"),
            generations_without_seconds(dir / "refit" / "part"));
  EXPECT_EQ(best_without_date(dir / "refit" / "whole"), best_without_date(dir / "refit" / "part"));

  // Without the stall test the same refit runs on.
  fs::create_directories(dir / "nostall");
  const std::string nostall_yaml = write_pendulum_fit(
      dir / "nostall", dir / "data", kWide, "{evaluations: " + std::to_string(stopped + 40) + "}");
  FitOverrides plain = whole;
  plain.out = (dir / "nostall" / "run").string();
  const FitSummary longer = FitSession(load_fit_config(nostall_yaml, plain), false).run();
  EXPECT_EQ(longer.stop_reason.find("stall_evaluations"), std::string::npos);
  EXPECT_GT(last_row_evaluations(dir / "nostall" / "run"), stopped);
  fs::remove_all(dir);
}

TEST(FitStallTest, BadStallSettingsAreNamed) {
  const fs::path dir = motoflex::testing::scratch_dir("fit_stall_bad");
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::string yaml = write_pendulum_fit(dir, dir, kWide, "{stall_relative: 1.5}");
  try {
    load_fit_config(yaml, {});
    ADD_FAILURE() << "accepted stall_relative 1.5";
  } catch (const std::exception& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find("stall_relative"), std::string::npos) << message;
    EXPECT_NE(message.find("fit.yaml"), std::string::npos) << message;
  }
  fs::remove_all(dir);
}

}  // namespace
}  // namespace motoflex
