#pragma once

#include <optional>

#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"

namespace motoflex::detail {

// Reads `excitation:` of a scenario's `motion` mapping:
//   excitation: {kind: multisine|chirp, amplitude_rad: 0.15, f0_hz: 0.2, f1_hz: 2.0,
//                duration_s: 10, rate_hz: 100, ramp_s: 0.5}
// around the robot's stand pose, inside its joint limits (motion/excitation.hpp). Returns
// nullopt when `motion` has no `excitation` key; throws InputError at the offending field.
std::optional<CommandTrajectory> excitation_motion_from_yaml(const YamlValue& motion,
                                                             const RobotModel& model);

}  // namespace motoflex::detail
