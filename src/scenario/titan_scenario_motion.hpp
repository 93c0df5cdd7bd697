#pragma once

#include <optional>
#include <string>

#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"

namespace motoflex::detail {

struct TitanScenarioMotion {
  CommandTrajectory commands;
  double rate_hz = 100.0;
  std::string description;
};

// Reads the TITAN-VIII motions of a scenario's `motion` mapping (seed 000):
//   titan_crawl:  {posture: A, periods: 1, rate_hz: 100, servo_lead: true}
//   titan_updown: {posture: A, amplitude_m: 0.03, period_s: 4, periods: 1, rate_hz: 100,
//                  servo_lead: true}
//   titan_stand:  {duration_s: 5, posture: A, rate_hz: 100}
// servo_lead (default: on with the velocity servo) adds θ̇_plan / k_d to the commands so that
// the velocity servo follows the plan without its 1/k_d lag (titan_gait.hpp); it needs the
// velocity servo. Returns nullopt when `motion` holds none of these keys. Throws InputError at
// the offending field for bad values, a robot that is not TITAN-VIII-like, or a plan the legs
// cannot reach.
std::optional<TitanScenarioMotion> titan_motion_from_yaml(const YamlValue& motion,
                                                          const RobotModel& model,
                                                          const ParameterSet& parameters,
                                                          const std::string& servo);

}  // namespace motoflex::detail
