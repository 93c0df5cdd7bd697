#pragma once

// Internal to the scenario loader: the `physics:` section (step, solver, sub-steps, structure)
// with the command line's overrides on top.

#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/scenario/scenario.hpp"

namespace motoflex::detail {

struct ScenarioPhysics {
  StructureOptions structure;
  RolloutOptions rollout;
};

// Reads `physics:` (absent: defaults) and applies `overrides`. Reports every problem of the
// section at once.
ScenarioPhysics read_scenario_physics(const std::optional<YamlValue>& physics,
                                      const ScenarioOverrides& overrides);

}  // namespace motoflex::detail
