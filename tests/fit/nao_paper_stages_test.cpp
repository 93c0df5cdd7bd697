// The staged fit of the paper's problem (scenarios/fit/nao_paper_short.yaml, then
// nao_paper_long.yaml --start-from the first, then nao_paper_whole.yaml --start-from the second)
// must search exactly nao_paper.yaml's problem:
// the same free parameters, bounds, scales and starts, the same logs; only the scoring window,
// the strategy and budget, the LM finish of stage 1 and the later stages' holding of what stage
// 1 identified differ.

#include <gtest/gtest.h>

#include <string>

#include "motoflex/fit/fit_spec.hpp"

namespace motoflex {
namespace {

const std::string kFitDir = std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/fit/";

void expect_same_problem(const FitSpec& paper, const FitSpec& stage) {
  ASSERT_EQ(stage.free.size(), paper.free.size()) << stage.path;
  for (std::size_t i = 0; i < paper.free.size(); ++i) {
    const FreeParameterSpec& a = paper.free[i];
    const FreeParameterSpec& b = stage.free[i];
    EXPECT_EQ(b.pattern, a.pattern) << stage.path;
    EXPECT_EQ(b.lower, a.lower) << a.pattern;
    EXPECT_EQ(b.upper, a.upper) << a.pattern;
    EXPECT_EQ(b.start, a.start) << a.pattern;
    EXPECT_EQ(b.log_scale, a.log_scale) << a.pattern;
    EXPECT_EQ(b.each, a.each) << a.pattern;
  }
  EXPECT_EQ(stage.scenario_path, paper.scenario_path);
  ASSERT_EQ(stage.train_data.size(), paper.train_data.size());
  EXPECT_EQ(stage.train_data[0].path, paper.train_data[0].path);
  ASSERT_EQ(stage.validation_data.size(), paper.validation_data.size());
  EXPECT_EQ(stage.validation_data[0].path, paper.validation_data[0].path);
  EXPECT_EQ(stage.fixed, paper.fixed);
  EXPECT_EQ(stage.fitness_m, paper.fitness_m);
}

TEST(NaoPaperStages, EveryStageSearchesThePapersProblem) {
  const FitSpec paper = load_fit_spec(kFitDir + "nao_paper.yaml");
  const FitSpec short_stage = load_fit_spec(kFitDir + "nao_paper_short.yaml");
  const FitSpec long_stage = load_fit_spec(kFitDir + "nao_paper_long.yaml");
  expect_same_problem(paper, short_stage);
  expect_same_problem(paper, long_stage);
  EXPECT_EQ(short_stage.window_s, 2.0);
  EXPECT_TRUE(short_stage.polish.lm());
  EXPECT_TRUE(
      short_stage.polish.reports_uncertainty());  // stage 2 holds what these intervals identify
  EXPECT_FALSE(short_stage.hold_identified);
  EXPECT_EQ(long_stage.window_s, 4.0);
  EXPECT_TRUE(long_stage.hold_identified);
  const FitSpec whole_stage = load_fit_spec(kFitDir + "nao_paper_whole.yaml");
  expect_same_problem(paper, whole_stage);
  EXPECT_EQ(whole_stage.window_s, 0.0);  // the fitness
  EXPECT_TRUE(whole_stage.hold_identified);
  EXPECT_EQ(paper.window_s, 0.0);  // the target: the whole logs
}

}  // namespace
}  // namespace motoflex
