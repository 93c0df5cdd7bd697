#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>

#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/motion/nao_walk.hpp"

namespace motoflex::detail {

struct NaoScenarioMotion {
  CommandTrajectory commands;
  double rate_hz = 100.0;
  std::string description;
  std::shared_ptr<const NaoWalkPlan> walk_plan;  // walks only
};

// Reads the Nao motions of a scenario's `motion` mapping:
//   walk: {speed_mm_s: 100, step_duration_s: 1.0, step_height_m: 0.02, double_support_ratio: 0.2,
//          com_height_m: 0.24, foot_spacing_m: 0.10, start_s: 1, stop_s: 1, duration_s: 10,
//          rate_hz: 100, zmp_offset_x_m: 0.015, zmp_offset_y_m: 0.02, zmp_travel_x_m: 0.04,
//          zmp_transfer_smoothing: 0, toe_off_rad: 0, heel_strike_rad: 0, torso_offset_x_m: 0,
//          preview_s: 1.6, first_swing: right}                           (NaoWalkParams)
//   kick: {kick_leg: right, com_height_m: 0.24, reach_m: 0.09, kick_s: 0.3, ...} (NaoKickParams)
// Every key is optional (defaults of the params structs). `walk_options` replace numeric walk
// keys (ScenarioOverrides::walk_options). Returns nullopt when `motion` holds neither key.
// Throws InputError at the offending field for bad or unreachable values (the planner's message
// names the parameter; the error points at that key when the file has it), for a walk option
// that is not a numeric walk key, or when the robot is not a Nao.
std::optional<NaoScenarioMotion> nao_motion_from_yaml(
    const YamlValue& motion, const RobotModel& model,
    const std::map<std::string, double>& walk_options = {});

}  // namespace motoflex::detail
