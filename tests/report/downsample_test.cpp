// Thinning keeps what a reader looks for in a trace: its ends and its peaks.

#include "motoflex/report/downsample.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace motoflex::report {
namespace {

TEST(EnvelopeIndices, ShortTracesAreKeptWhole) {
  const std::vector<double> y = {3.0, 1.0, 4.0, 1.0, 5.0};
  EXPECT_EQ(envelope_indices(y, 5), (std::vector<std::size_t>{0, 1, 2, 3, 4}));
  EXPECT_EQ(envelope_indices(y, 2000).size(), 5u);
  EXPECT_TRUE(envelope_indices(std::vector<double>{}, 10).empty());
}

TEST(EnvelopeIndices, LongTracesKeepEndsAndEveryBucketsExtremesWithinTheBudget) {
  // A slow sine with two isolated one-sample spikes, far shorter than a bucket.
  std::vector<double> y(100000);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::sin(1e-4 * static_cast<double>(i));
  y[12345] = 50.0;
  y[77777] = -60.0;
  const std::size_t max_points = 2000;
  const std::vector<std::size_t> keep = envelope_indices(y, max_points);
  EXPECT_LE(keep.size(), max_points);
  EXPECT_GE(keep.size(), max_points - 2);  // the budget is used, not wasted
  EXPECT_TRUE(std::is_sorted(keep.begin(), keep.end()));
  EXPECT_EQ(std::adjacent_find(keep.begin(), keep.end()), keep.end());  // no duplicates
  EXPECT_EQ(keep.front(), 0u);
  EXPECT_EQ(keep.back(), y.size() - 1);
  EXPECT_NE(std::find(keep.begin(), keep.end(), 12345u), keep.end());
  EXPECT_NE(std::find(keep.begin(), keep.end(), 77777u), keep.end());
  // The kept points span the same range as the whole trace.
  double lo = y[keep[0]], hi = y[keep[0]];
  for (const std::size_t i : keep) {
    lo = std::min(lo, y[i]);
    hi = std::max(hi, y[i]);
  }
  EXPECT_EQ(lo, -60.0);
  EXPECT_EQ(hi, 50.0);
}

TEST(EnvelopeIndices, NanSamplesDoNotHideTheExtremes) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<double> y(1000, 0.0);
  for (std::size_t i = 1; i < 500; ++i) y[i] = nan;  // e.g. after a simulated fall
  y[700] = 9.0;
  const std::vector<std::size_t> keep = envelope_indices(y, 10);
  EXPECT_LE(keep.size(), 10u);
  EXPECT_NE(std::find(keep.begin(), keep.end(), 700u), keep.end());
}

TEST(EnvelopeIndices, ABudgetBelowFourIsFour) {
  std::vector<double> y(100);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = static_cast<double>(i % 7);
  const auto keep = envelope_indices(y, 1);
  EXPECT_LE(keep.size(), 4u);
  EXPECT_GE(keep.size(), 3u);
  EXPECT_EQ(keep.front(), 0u);
  EXPECT_EQ(keep.back(), 99u);
}

}  // namespace
}  // namespace motoflex::report
