#pragma once

// Starting values and search bounds of a robot's parameters, for robot folders written from a
// URDF (`motoflex init-robot`). Each law documents its own (ServoLawInfo::default_parameters);
// joint friction comes from the URDF's <dynamics> (joint_friction_defaults); the rollout-wide
// names have the table in robot_parameter_defaults.cpp.

#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {

// One entry per name rollout_parameter_names(model, servo) lists, in its order: the first
// default any actuator's law offers for it, else the joint-friction or rollout-wide one, else
// the model's own (the effects' neutral values, source "neutral (model effect)"), else
// [0, 0, 1] with source "NO DEFAULT" (a law without default_parameters). `hints` holds one
// entry per actuator. Throws std::invalid_argument for an unknown law.
std::vector<ParameterDefault> robot_parameter_defaults(const RobotModel& model,
                                                       const std::string& servo,
                                                       const std::vector<JointHints>& hints);

// The source string of a name nobody gives a default.
inline constexpr const char* kNoDefault = "NO DEFAULT";

}  // namespace motoflex
