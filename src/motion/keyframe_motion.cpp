#include "motoflex/motion/keyframe_motion.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace motoflex {

CommandTrajectory keyframe_trajectory(const std::vector<Keyframe>& keyframes, double rate_hz) {
  if (keyframes.size() < 2) throw std::invalid_argument("a keyframe motion needs >= 2 keyframes");
  if (!(rate_hz > 0.0)) throw std::invalid_argument("rate_hz must be positive");
  const std::size_t joints = keyframes.front().pose_rad.size();
  for (std::size_t k = 1; k < keyframes.size(); ++k) {
    if (!(keyframes[k].time_s > keyframes[k - 1].time_s)) {
      throw std::invalid_argument("keyframe times must strictly increase");
    }
    if (keyframes[k].pose_rad.size() != joints) {
      throw std::invalid_argument("keyframes must all have the same joints");
    }
  }
  const double start = keyframes.front().time_s;
  const double end = keyframes.back().time_s;
  const auto frames = static_cast<std::size_t>(std::floor((end - start) * rate_hz + 1e-9)) + 1;
  std::vector<double> times(frames), angles(frames * joints);
  std::size_t segment = 0;
  for (std::size_t f = 0; f < frames; ++f) {
    const double t = start + static_cast<double>(f) / rate_hz;
    times[f] = t - start;
    while (segment + 2 < keyframes.size() && keyframes[segment + 1].time_s <= t) ++segment;
    const Keyframe& a = keyframes[segment];
    const Keyframe& b = keyframes[segment + 1];
    const double u = std::clamp((t - a.time_s) / (b.time_s - a.time_s), 0.0, 1.0);
    const double blend = 0.5 - 0.5 * std::cos(std::numbers::pi * u);
    for (std::size_t j = 0; j < joints; ++j) {
      angles[f * joints + j] = a.pose_rad[j] + blend * (b.pose_rad[j] - a.pose_rad[j]);
    }
  }
  return CommandTrajectory(std::move(times), std::move(angles), joints);
}

}  // namespace motoflex
