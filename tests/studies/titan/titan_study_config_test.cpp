// scenarios/titan/paper.yaml holds the paper's settings, and mistakes in a study file are
// reported at their file, line and field (also by `motoflex titan`, with exit code 2).

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "cli/cli_test_support.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/studies/titan/titan_study_config.hpp"
#include "titan_study_test_support.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

TEST(TitanStudyConfig, PaperFileHoldsThePapersSettings) {
  const TitanStudyConfig& config = testing::titan_paper_config();
  const TitanPaperStudyPlan& plan = config.plan;
  EXPECT_EQ(plan.setup.rollout.servo, "velocity");
  EXPECT_EQ(plan.setup.rollout.solver, StepSolver::kStep);
  EXPECT_DOUBLE_EQ(plan.setup.rollout.dt_s, 0.001);
  EXPECT_DOUBLE_EQ(plan.setup.model->initial_clearance_m, 0.01);
  EXPECT_DOUBLE_EQ(plan.setup.parameters.get("contact.mu"), 0.5);
  EXPECT_DOUBLE_EQ(plan.setup.parameters.get("contact.slip"), 0.001);
  EXPECT_DOUBLE_EQ(plan.setup.parameters.get("contact.soft_erp"), 0.2);
  EXPECT_DOUBLE_EQ(plan.setup.parameters.get("contact.soft_cfm"), 1e-4);
  EXPECT_DOUBLE_EQ(plan.setup.parameters.get("joint.FL_J3.gain_per_s"), 4.0);  // Table I
  EXPECT_DOUBLE_EQ(plan.setup.parameters.get("joint.FL_J3.torque_max_nm"), 25.7);
  EXPECT_EQ(plan.stand.posture, TitanPosture::kA);
  EXPECT_DOUBLE_EQ(plan.stand.cut_after_touchdown_s, 0.03);
  EXPECT_DOUBLE_EQ(plan.stand.converge_fraction, 0.05);
  EXPECT_EQ(plan.crawl_postures.size(), 4u);
  EXPECT_EQ(plan.crawl.periods, 3);
  EXPECT_DOUBLE_EQ(plan.crawl.exchange_from_s, 2.4);
  EXPECT_DOUBLE_EQ(plan.timing_crawl_s, 10.0);
}

class TitanStudyConfigErrors : public ::testing::Test {
 protected:
  std::string write(const std::string& body) {
    dir_ = testing::fresh_dir("titan_study_config");
    const fs::path path = dir_ / "study.yaml";
    std::ofstream(path) << "robot: " << MOTOFLEX_SOURCE_DIR << "/scenarios/robots/titan8\n" << body;
    return path.string();
  }
  void TearDown() override { fs::remove_all(dir_); }
  fs::path dir_;
};

TEST_F(TitanStudyConfigErrors, ReportFileLineAndField) {
  const auto expect_error = [&](const std::string& body, int line, const std::string& field,
                                const std::string& words) {
    const std::string path = write(body);
    try {
      load_titan_study_config(path);
      ADD_FAILURE() << "accepted: " << body;
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), path);
      EXPECT_EQ(error.line(), line) << error.what();
      EXPECT_EQ(error.field(), field) << error.what();
      EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
    }
  };
  expect_error("crawl:\n  postures: [A, E]\n", 3, "crawl.postures[1]", "A, B, C or D");
  expect_error("crawl:\n  period: 3\n", 3, "crawl.period", "did you mean 'periods'");
  expect_error("static: {duration_s: -1}\n", 2, "static.duration_s", "positive");
  expect_error("servo: motoflex\n", 2, "servo", "velocity");
  expect_error("contact: {mu: 0.5, slipp: 0.001}\n", 2, "contact.slipp", "slip");
  expect_error("updown: {periods: 1}\n", 2, "updown.periods", ">= 2");
  expect_error("crawl: {exchange_window_s: [3.0, 2.0]}\n", 2, "crawl.exchange_window_s",
               "from < to");
  expect_error("physics: {initial_clearance_m: 0.5}\n", 2, "physics.initial_clearance_m",
               "[0, 0.1]");
}

TEST_F(TitanStudyConfigErrors, CommandLineSaysWhereAndExitsWithTwo) {
  const std::string path = write("timing: {crawl_s: ten}\n");
  const testing::CommandResult result =
      testing::run_motoflex("titan " + path + " --out " + (dir_ / "out").string());
  EXPECT_EQ(result.exit_code, 2);
  EXPECT_NE(result.stderr_text.find(path + ":2: timing.crawl_s:"), std::string::npos)
      << result.stderr_text;
  EXPECT_FALSE(fs::exists(dir_ / "out" / "titan.json"));
}

}  // namespace
}  // namespace motoflex
