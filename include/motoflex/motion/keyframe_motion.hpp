#pragma once

#include <vector>

#include "motoflex/motion/command_trajectory.hpp"

namespace motoflex {

struct Keyframe {
  double time_s = 0.0;
  std::vector<double> pose_rad;  // actuated joints, model order
};

// Samples a keyframe motion at `rate_hz` from the first to the last keyframe. Between two
// keyframes every joint follows a cosine blend, so velocity is zero at each keyframe and the
// motion is smooth (C¹). Throws std::invalid_argument unless there are >= 2 keyframes with
// strictly increasing times, equal pose sizes and rate_hz > 0.
CommandTrajectory keyframe_trajectory(const std::vector<Keyframe>& keyframes, double rate_hz);

}  // namespace motoflex
