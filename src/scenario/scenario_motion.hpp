#pragma once

// Internal to the scenario loader: a scenario's `motion:` section (exactly one of log,
// keyframes, stand, walk, kick, titan_*, excitation) turned into commanded angles.

#include <memory>
#include <string>

#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/scenario/scenario.hpp"

namespace motoflex::detail {

// Fills scenario.commands, log_rate_hz, motion_description (and walk_plan, log_parameters)
// from `motion`; scenario.model, parameters and rollout must be set.
void read_scenario_motion(const YamlValue& motion, const ScenarioOverrides& overrides,
                          Scenario& scenario);

}  // namespace motoflex::detail
