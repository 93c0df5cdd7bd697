#pragma once

// Whether the training logs excite every actuated joint. A joint the excitation leaves (nearly)
// still shows none of its friction, damping or servo behaviour, so its parameters cannot be
// identified; a fit says so before it starts (a multisine with too few harmonics can leave a
// quadruped's joints motionless without anyone noticing).

#include <string>
#include <vector>

#include "motoflex/fit/fitness.hpp"

namespace motoflex {

struct StillJoint {
  std::string joint;
  double range = 0.0;  // max − min of the measured angle over every log (rad, m for a slider)
};

// Range below which a joint counts as still: 0.01 rad (0.57°) on a hinge, 1 mm on a slider.
inline constexpr double kStillRange_rad = 0.01;
inline constexpr double kStillRange_m = 0.001;

// The actuated joints of `model` whose measured angle moves less than the still range over all
// of `cases` (each case's measured_rad is frame-major in model order).
std::vector<StillJoint> still_joints(const RobotModel& model, const std::vector<FitCase>& cases);

// One warning line per still joint ("joint 'x' moves 0.002 rad in the training logs: ...").
std::vector<std::string> excitation_warnings(const RobotModel& model,
                                             const std::vector<FitCase>& cases);

}  // namespace motoflex
