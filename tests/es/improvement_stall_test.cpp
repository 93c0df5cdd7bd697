// ImprovementStall: the search stops exactly `window` evaluations after the last improvement
// larger than the relative tolerance; smaller ones do not count; the state is two numbers, and
// restoring them continues exactly.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "motoflex_es/improvement_stall.hpp"

namespace motoflex_es {
namespace {

TEST(ImprovementStallTest, StallsExactlyOneWindowAfterTheLastRealImprovement) {
  ImprovementStall stall(100, 1e-3);
  EXPECT_FALSE(stall.update(1.0, 10));  // the first value anchors the window at 10
  EXPECT_EQ(stall.anchor_evaluations(), 10u);
  EXPECT_FALSE(stall.update(0.9995, 50));  // 0.05 % < 0.1 %: not an improvement
  EXPECT_EQ(stall.anchor_fitness(), 1.0);
  EXPECT_FALSE(stall.update(0.9, 60));  // 10 %: the window starts again at 60
  EXPECT_EQ(stall.anchor_evaluations(), 60u);
  EXPECT_EQ(stall.anchor_fitness(), 0.9);
  EXPECT_FALSE(stall.update(0.9, 159));
  EXPECT_TRUE(stall.update(0.8996, 160));  // 160 = 60 + 100, and 0.04 % does not count
  EXPECT_TRUE(stall.stalled());
}

TEST(ImprovementStallTest, ZeroWindowNeverStallsAndNanNeverImproves) {
  ImprovementStall off(0, 1e-3);
  EXPECT_FALSE(off.enabled());
  for (std::uint64_t e = 1; e < 100000; e *= 3) EXPECT_FALSE(off.update(1.0, e));

  ImprovementStall stall(20, 0.0);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(stall.update(nan, 5));
  EXPECT_TRUE(stall.update(nan, 20));  // nothing valid for a whole window from 0
  stall.restore(std::numeric_limits<double>::infinity(), 0);
  EXPECT_FALSE(stall.update(2.0, 21));
  EXPECT_FALSE(stall.update(nan, 40));
  EXPECT_EQ(stall.anchor_fitness(), 2.0);
  EXPECT_TRUE(stall.update(2.0, 41));  // with tolerance 0 an equal value does not improve
  EXPECT_THROW(ImprovementStall(10, -1.0), std::invalid_argument);
}

TEST(ImprovementStallTest, RestoringTheTwoNumbersContinuesExactly) {
  // One tracker fed a whole sequence against one restored halfway: same answers.
  const double best[] = {5.0, 4.0, 3.99, 3.5, 3.5, 3.499, 3.2, 3.2, 3.2, 3.2, 3.2, 3.2};
  ImprovementStall whole(40, 0.01);
  ImprovementStall first(40, 0.01);
  bool whole_result[12];
  for (int g = 0; g < 12; ++g) whole_result[g] = whole.update(best[g], 10u * (g + 1));
  for (int g = 0; g < 6; ++g) first.update(best[g], 10u * (g + 1));
  ImprovementStall second(40, 0.01);
  second.restore(first.anchor_fitness(), first.anchor_evaluations());
  for (int g = 6; g < 12; ++g) {
    EXPECT_EQ(second.update(best[g], 10u * (g + 1)), whole_result[g]) << g;
  }
  EXPECT_EQ(second.anchor_evaluations(), whole.anchor_evaluations());
  EXPECT_TRUE(whole.stalled());  // the last improvement (3.2) came at 70; 70 + 40 = 110 <= 120
  EXPECT_EQ(whole.anchor_evaluations(), 70u);
}

}  // namespace
}  // namespace motoflex_es
