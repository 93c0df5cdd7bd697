#include "motoflex/sim/joint_encoder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace motoflex {
namespace {

constexpr double kDt = 1e-3;

// A test angle sequence that is not linear, so interpolation weights show.
double angle_at(int step) {
  return 0.01 * step * step - 0.3 * step;
}

JointEncoder make_encoder(const EncoderParams& params) {
  return JointEncoder(params, kDt, RandomStream({1, 2, 3}));
}

TEST(JointEncoderTest, ExactEncoderReadsTheLatestAngle) {
  JointEncoder encoder = make_encoder({});
  for (int k = 0; k < 20; ++k) {
    encoder.push(angle_at(k));
    EXPECT_EQ(encoder.read(), angle_at(k));
  }
}

TEST(JointEncoderTest, TwelveBitsQuantiseToTwoPiOver4096) {
  JointEncoder encoder = make_encoder({.resolution_bits = 12});
  const double step_rad = 2.0 * std::numbers::pi / 4096.0;
  EXPECT_DOUBLE_EQ(encoder.resolution_rad(), step_rad);
  // Round to the nearest multiple.
  encoder.push(0.3 * step_rad);
  EXPECT_EQ(encoder.read(), 0.0);
  encoder.push(0.7 * step_rad);
  EXPECT_DOUBLE_EQ(encoder.read(), step_rad);
  encoder.push(-5.6 * step_rad);
  EXPECT_DOUBLE_EQ(encoder.read(), -6.0 * step_rad);
  // Over a sweep: every reading is a multiple of the step and within half a step of the truth.
  for (int i = 0; i < 1000; ++i) {
    const double angle_rad = -1.0 + 0.002137 * i;
    encoder.push(angle_rad);
    const double reading = encoder.read();
    EXPECT_NEAR(reading / step_rad, std::round(reading / step_rad), 1e-9);
    EXPECT_LE(std::abs(reading - angle_rad), 0.5 * step_rad + 1e-15);
  }
}

TEST(JointEncoderTest, WholeStepDelayReturnsTheAngleFromThatManyStepsAgo) {
  JointEncoder encoder = make_encoder({.delay_s = 10e-3});  // 10 steps at 1 ms
  for (int k = 0; k < 50; ++k) {
    encoder.push(angle_at(k));
    // Before 10 steps of history the oldest stored angle (the first one) stands in.
    EXPECT_EQ(encoder.read(), angle_at(k >= 10 ? k - 10 : 0)) << "step " << k;
  }
}

TEST(JointEncoderTest, FractionalDelayInterpolatesLinearly) {
  JointEncoder encoder = make_encoder({.delay_s = 2.25e-3});  // 2.25 steps
  for (int k = 0; k < 30; ++k) {
    encoder.push(angle_at(k));
    if (k < 3) continue;
    EXPECT_NEAR(encoder.read(), 0.75 * angle_at(k - 2) + 0.25 * angle_at(k - 3), 1e-12)
        << "step " << k;
  }
}

TEST(JointEncoderTest, ResetFillsTheHistory) {
  JointEncoder encoder = make_encoder({.delay_s = 5e-3});
  for (int k = 0; k < 20; ++k) encoder.push(angle_at(k));
  encoder.reset(0.7);
  EXPECT_EQ(encoder.read(), 0.7);
  // The new angles appear after the delay; until then the reset angle is read.
  for (int k = 0; k < 5; ++k) {
    encoder.push(1.0 + k);
    EXPECT_EQ(encoder.read(), 0.7) << "push " << k;
  }
  encoder.push(6.0);
  EXPECT_EQ(encoder.read(), 1.0);
}

TEST(JointEncoderTest, ReadBeforeAnyPushIsZeroAngle) {
  JointEncoder encoder = make_encoder({.delay_s = 3e-3, .offset_rad = 0.1});
  EXPECT_EQ(encoder.read(), 0.1);
}

TEST(JointEncoderTest, OffsetAddsBeforeQuantisation) {
  JointEncoder exact = make_encoder({.offset_rad = 0.05});
  exact.push(0.2);
  EXPECT_DOUBLE_EQ(exact.read(), 0.25);
  // 0.4 + 0.6 steps of offset round up to the next step; the offset alone would not.
  JointEncoder coarse =
      make_encoder({.resolution_bits = 8, .offset_rad = 0.6 * 2 * std::numbers::pi / 256});
  const double step_rad = 2.0 * std::numbers::pi / 256.0;
  coarse.push(0.4 * step_rad);
  EXPECT_DOUBLE_EQ(coarse.read(), step_rad);
}

TEST(JointEncoderTest, NoiseHasTheConfiguredStandardDeviation) {
  const double noise_rad = 0.002;
  JointEncoder encoder = make_encoder({.noise_rad = noise_rad});
  encoder.reset(0.5);
  const int reads = 100000;
  double sum = 0.0;
  double sum_squares = 0.0;
  for (int i = 0; i < reads; ++i) {
    const double error_rad = encoder.read() - 0.5;
    sum += error_rad;
    sum_squares += error_rad * error_rad;
  }
  const double mean_rad = sum / reads;
  const double std_rad = std::sqrt(sum_squares / reads - mean_rad * mean_rad);
  // Standard error of the mean σ/sqrt(n); of the sample std about σ/sqrt(2n) = 0.22 %.
  EXPECT_NEAR(mean_rad, 0.0, 4.0 * noise_rad / std::sqrt(reads));
  EXPECT_NEAR(std_rad, noise_rad, 0.03 * noise_rad);
}

TEST(JointEncoderTest, NoiseIsReproducibleFromTheStream) {
  JointEncoder a = make_encoder({.noise_rad = 0.01});
  JointEncoder b = make_encoder({.noise_rad = 0.01});
  JointEncoder other(EncoderParams{.noise_rad = 0.01}, kDt, RandomStream({1, 2, 4}));
  a.reset(0.0);
  b.reset(0.0);
  other.reset(0.0);
  for (int i = 0; i < 100; ++i) {
    const double reading = a.read();
    EXPECT_EQ(reading, b.read());
    EXPECT_NE(reading, other.read());
  }
}

TEST(JointEncoderTest, RejectsInvalidParameters) {
  EXPECT_THROW(make_encoder({.delay_s = -1e-3}), std::invalid_argument);
  EXPECT_THROW(make_encoder({.noise_rad = -0.1}), std::invalid_argument);
  EXPECT_THROW(make_encoder({.resolution_bits = -1}), std::invalid_argument);
  EXPECT_THROW(make_encoder({.resolution_bits = 33}), std::invalid_argument);
  EXPECT_NO_THROW(make_encoder({.resolution_bits = 32}));
  EXPECT_THROW(JointEncoder({}, 0.0, RandomStream({1})), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
