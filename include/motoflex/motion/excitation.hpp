#pragma once

#include <string>
#include <vector>

#include "motoflex/motion/command_trajectory.hpp"

namespace motoflex {

// Excitation motions for identifiability (beyond the MoToFlex paper): every actuated joint
// moves around a base pose so that friction, backlash, motor and gear parameters show in the
// measured angles. Meant for a robot held by its torso (no ground contact).
struct ExcitationParams {
  enum class Kind {
    kChirp,      // logarithmic sweep f0 → f1, each joint's sweep shifted in time so the
                 // joints are not moving in lock-step
    kMultisine,  // sum of sines with Schroeder phases; joint j gets every n-th harmonic
                 // (n = joints) of f0, so the joints' spectra do not overlap
  };
  Kind kind = Kind::kMultisine;
  double amplitude_rad = 0.15;  // peak deviation from the base pose
  double f0_hz = 0.2;           // lowest frequency (multisine: fundamental)
  double f1_hz = 2.0;           // highest frequency
  double duration_s = 10.0;
  double rate_hz = 100.0;
  double ramp_s = 0.5;  // smooth fade-in and fade-out
};

// Samples the motion for joints whose base pose and limits are given (model actuator order).
// Amplitudes are reduced per joint so the motion stays 0.02 rad inside the limits. Throws
// std::invalid_argument naming the parameter for non-positive durations, rates or amplitudes,
// f1 <= f0, or a rate below 5·f1.
CommandTrajectory excitation_trajectory(const ExcitationParams& params,
                                        const std::vector<double>& base_pose_rad,
                                        const std::vector<double>& lower_rad,
                                        const std::vector<double>& upper_rad);

}  // namespace motoflex
