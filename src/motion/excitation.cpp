#include "motoflex/motion/excitation.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace motoflex {
namespace {

constexpr double kLimitMargin_rad = 0.02;

void require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// Smooth 0 → 1 → 0 envelope with cosine ramps of length ramp_s at both ends.
double envelope(double t, double duration_s, double ramp_s) {
  if (ramp_s <= 0.0) return 1.0;
  const double edge = std::min({t, duration_s - t, ramp_s});
  if (edge <= 0.0) return 0.0;
  return 0.5 - 0.5 * std::cos(std::numbers::pi * edge / ramp_s);
}

}  // namespace

CommandTrajectory excitation_trajectory(const ExcitationParams& params,
                                        const std::vector<double>& base_pose_rad,
                                        const std::vector<double>& lower_rad,
                                        const std::vector<double>& upper_rad) {
  require(params.duration_s > 0.0, "duration_s must be positive");
  require(params.rate_hz > 0.0, "rate_hz must be positive");
  require(params.amplitude_rad > 0.0, "amplitude_rad must be positive");
  require(params.f0_hz > 0.0, "f0_hz must be positive");
  require(params.f1_hz > params.f0_hz, "f1_hz must exceed f0_hz");
  require(params.rate_hz >= 5.0 * params.f1_hz,
          "rate_hz = " + std::to_string(params.rate_hz) +
              " must be at least 5·f1_hz = " + std::to_string(5.0 * params.f1_hz));
  require(params.ramp_s >= 0.0 && 2.0 * params.ramp_s < params.duration_s,
          "ramp_s must be >= 0 and shorter than half the duration");
  const std::size_t joints = base_pose_rad.size();
  require(joints > 0 && lower_rad.size() == joints && upper_rad.size() == joints,
          "base pose and limits must have one entry per joint");

  std::vector<double> amplitude(joints);
  for (std::size_t j = 0; j < joints; ++j) {
    const double room = std::min(upper_rad[j] - base_pose_rad[j], base_pose_rad[j] - lower_rad[j]) -
                        kLimitMargin_rad;
    require(room > 0.0, "base pose of joint " + std::to_string(j) + " is at its limit");
    amplitude[j] = std::min(params.amplitude_rad, room);
  }

  // Multisine: harmonics k·f0 in [f0, f1], dealt out to the joints in turn; Schroeder phases
  // −π·k·(k−1)/K keep the crest factor low.
  std::vector<std::vector<int>> harmonics(joints);
  const int highest = static_cast<int>(std::floor(params.f1_hz / params.f0_hz + 1e-9));
  for (int k = 1; k <= highest; ++k) harmonics[(k - 1) % joints].push_back(k);
  std::vector<double> peak(joints, 1.0);

  const auto frames =
      static_cast<std::size_t>(std::floor(params.duration_s * params.rate_hz + 1e-9)) + 1;
  std::vector<double> times(frames), angles(frames * joints);
  const double two_pi = 2.0 * std::numbers::pi;
  const double log_ratio = std::log(params.f1_hz / params.f0_hz);
  auto raw = [&](std::size_t j, double t) {
    if (params.kind == ExcitationParams::Kind::kChirp) {
      // Logarithmic chirp, started at a joint-specific offset of the sweep (wrapping around).
      const double offset = params.duration_s * static_cast<double>(j) / joints;
      const double tau = std::fmod(t + offset, params.duration_s);
      const double rate = log_ratio / params.duration_s;
      const double phase = two_pi * params.f0_hz * (std::exp(rate * tau) - 1.0) / rate;
      return (j % 2 == 0 ? 1.0 : -1.0) * std::sin(phase);
    }
    double sum = 0.0;
    const auto count = static_cast<double>(harmonics[j].size());
    for (const int k : harmonics[j]) {
      const double schroeder = -std::numbers::pi * k * (k - 1) / std::max(count, 1.0);
      sum += std::sin(two_pi * k * params.f0_hz * t + schroeder);
    }
    return sum;
  };
  if (params.kind == ExcitationParams::Kind::kMultisine) {
    // Normalise each joint's multisine to a unit peak over the motion.
    for (std::size_t j = 0; j < joints; ++j) {
      double largest = 0.0;
      for (std::size_t f = 0; f < frames; ++f) {
        largest = std::max(largest, std::abs(raw(j, static_cast<double>(f) / params.rate_hz)));
      }
      peak[j] = largest > 0.0 ? largest : 1.0;
    }
  }
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = static_cast<double>(f) / params.rate_hz;
    times[f] = t;
    const double gain = envelope(t, params.duration_s, params.ramp_s);
    for (std::size_t j = 0; j < joints; ++j) {
      angles[f * joints + j] = base_pose_rad[j] + gain * amplitude[j] * raw(j, t) / peak[j];
    }
  }
  return CommandTrajectory(std::move(times), std::move(angles), joints);
}

}  // namespace motoflex
