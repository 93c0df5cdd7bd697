#include "motoflex/motion/excitation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>

namespace motoflex {
namespace {

const std::vector<double> kBase = {0.0, -0.3, 0.6, -0.3};
const std::vector<double> kLower = {-0.4, -1.5, -0.09, -1.2};
const std::vector<double> kUpper = {0.8, 0.48, 2.1, 0.1};  // joint 3 has only 0.4 rad of room

TEST(Excitation, StaysInsideLimitsStartsAndEndsAtTheBasePose) {
  for (auto kind : {ExcitationParams::Kind::kChirp, ExcitationParams::Kind::kMultisine}) {
    ExcitationParams params;
    params.kind = kind;
    params.amplitude_rad = 0.5;
    const CommandTrajectory motion = excitation_trajectory(params, kBase, kLower, kUpper);
    ASSERT_EQ(motion.frames(), 1001u);
    double largest = 0.0;
    for (std::size_t f = 0; f < motion.frames(); ++f) {
      for (std::size_t j = 0; j < kBase.size(); ++j) {
        const double a = motion.angle_rad(f, j);
        ASSERT_GE(a, kLower[j] + 0.02 - 1e-12);
        ASSERT_LE(a, kUpper[j] - 0.02 + 1e-12);
        if (j == 0) largest = std::max(largest, std::abs(a - kBase[0]));
      }
    }
    EXPECT_GT(largest, 0.37);  // joint 0: all of its 0.38 rad of room (0.4 − margin) is used
    for (std::size_t j = 0; j < kBase.size(); ++j) {
      EXPECT_NEAR(motion.angle_rad(0, j), kBase[j], 1e-12);
      EXPECT_NEAR(motion.angle_rad(motion.frames() - 1, j), kBase[j], 1e-12);
    }
  }
}

TEST(Excitation, MultisineJointsExciteDisjointFrequencies) {
  ExcitationParams params;
  params.duration_s = 20.0;  // 4 fundamental periods at f0 = 0.2 Hz
  params.f0_hz = 0.2;
  params.f1_hz = 2.0;
  params.ramp_s = 0.0;
  const CommandTrajectory motion = excitation_trajectory(params, kBase, kLower, kUpper);
  const std::size_t n = motion.frames() - 1;  // one whole number of periods
  // DFT bin of harmonic k of f0 over 20 s is 4k. Each joint has energy only at its harmonics.
  for (std::size_t j = 0; j < kBase.size(); ++j) {
    for (int k = 1; k <= 10; ++k) {
      std::complex<double> sum = 0.0;
      for (std::size_t f = 0; f < n; ++f) {
        const double phase = -2.0 * std::numbers::pi * 4.0 * k * static_cast<double>(f) / n;
        sum += (motion.angle_rad(f, j) - kBase[j]) * std::polar(1.0, phase);
      }
      const bool mine = static_cast<std::size_t>((k - 1) % kBase.size()) == j;
      if (mine) {
        EXPECT_GT(std::abs(sum) / n, 0.01) << "joint " << j << " harmonic " << k;
      } else {
        EXPECT_LT(std::abs(sum) / n, 1e-9) << "joint " << j << " harmonic " << k;
      }
    }
  }
}

TEST(Excitation, RejectsBadParametersByName) {
  ExcitationParams params;
  params.f1_hz = 30.0;  // needs 150 Hz
  try {
    excitation_trajectory(params, kBase, kLower, kUpper);
    FAIL();
  } catch (const std::invalid_argument& error) {
    EXPECT_NE(std::string(error.what()).find("rate_hz"), std::string::npos);
  }
  params = ExcitationParams{};
  params.amplitude_rad = 0.0;
  EXPECT_THROW(excitation_trajectory(params, kBase, kLower, kUpper), std::invalid_argument);
}

}  // namespace
}  // namespace motoflex
