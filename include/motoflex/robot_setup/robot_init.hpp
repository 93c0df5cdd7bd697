#pragma once

// `motoflex init-robot FILE.urdf --out DIR`: a robot folder written from a URDF, with every
// assumption made on the way listed.

#include <optional>
#include <string>
#include <vector>

#include "motoflex/robot_setup/urdf_hints.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {

struct RobotInitOptions {
  std::string urdf_path;
  std::string out_dir;  // created if missing; its robot.yaml is replaced
  // Servo law of every actuated joint; empty = kDefaultInitServo when registered, else
  // "velocity".
  std::string servo;
  // Welded base (an arm, a bench) or free-floating (a legged robot); empty = guessed: floating
  // when the URDF's root joint floats or two or more leaf links share the lowest height.
  std::optional<bool> fixed_base;
  double check_duration_s = 1.0;  // the stand pose held this long to show the robot simulates
};
inline constexpr const char* kDefaultInitServo = "pd_torque";

struct RobotInitResult {
  std::string robot_yaml;  // the file written
  std::vector<Assumption> assumptions;
  RolloutResult check;  // the stand pose held with every parameter at its default
};

// Reads the URDF (every problem at once: InputErrors), writes <out_dir>/robot.yaml, loads it
// back as any robot folder (load_robot) and holds its stand pose. Every movable joint is
// actuated (revolute, continuous, prismatic; one group per joint) except <mimic> followers and
// joints that move only massless links (held); fixed joints and frame links are lumped; a pair
// of joints around a massless link whose axes cross at right angles becomes a universal joint.
// Parameters come from the laws' default_parameters, the URDF's <limit> and <dynamics> (after
// screen_urdf_joint) and the rollout's own table (robot_parameter_defaults.hpp).
RobotInitResult init_robot(const RobotInitOptions& options);

// The assumptions as one aligned text table (header, one row each).
std::string assumptions_table(const std::vector<Assumption>& assumptions);

}  // namespace motoflex
