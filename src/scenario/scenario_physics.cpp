#include "scenario_physics.hpp"

#include <cmath>

#include "motoflex/core/error_collector.hpp"

namespace motoflex {

std::optional<StepSolver> parse_step_solver(const std::string& text) {
  if (text == "step") return StepSolver::kStep;
  if (text == "sparse") return StepSolver::kSparseStep;
  if (text == "quick") return StepSolver::kQuickStep;
  return std::nullopt;
}

void read_step_settings(const YamlValue& physics, RolloutOptions& rollout) {
  rollout.dt_s = physics.get_double("dt_s", rollout.dt_s);
  if (!(rollout.dt_s > 0.0 && rollout.dt_s <= 0.01)) {
    physics.at("dt_s").fail("must be in (0, 0.01] s");
  }
  if (const auto solver = physics.find("solver")) {
    const auto parsed = parse_step_solver(solver->as_string());
    if (!parsed) solver->fail(kStepSolverChoices);
    rollout.solver = *parsed;
  }
}

namespace detail {
namespace {

// Limits on what sizes the work of one rollout (a typo must not hang a run for hours).
constexpr int kMaxQuickStepIterations = 10000;
constexpr int kMaxGearSubsteps = 10000;
constexpr double kMaxSettle_s = 60.0;

void read_flex_model(const YamlValue& physics, RolloutOptions& rollout) {
  const auto flex_model = physics.find("flex_model");
  if (!flex_model) return;
  const std::string name = flex_model->as_string();
  if (name == "implicit") {
    rollout.flex_model = FlexModel::kImplicit;
  } else if (name == "explicit_cfm") {
    rollout.flex_model = FlexModel::kExplicitCfm;
  } else {
    flex_model->fail("expected 'implicit' or 'explicit_cfm'");
  }
}

// Reads the keys of `physics` that are present on top of `out` (a truth file's section goes on
// top of a scenario's).
void read_physics_section(const YamlValue& physics, ScenarioPhysics& out) {
  physics.require_keys_within({"dt_s", "solver", "quickstep_iterations", "quickstep_w",
                               "quickstep_seed", "gear_substeps", "flex_sub_bodies", "flex_model",
                               "max_contacts", "universal_joints", "settle_s", "hold_torso",
                               "float_state"});
  RolloutOptions& rollout = out.rollout;
  StructureOptions& structure = out.structure;
  ErrorCollector errors;
  errors.check([&] { read_step_settings(physics, rollout); });
  errors.check([&] {
    rollout.quickstep_iterations =
        physics.get_int("quickstep_iterations", rollout.quickstep_iterations);
    if (rollout.quickstep_iterations < 1 ||
        rollout.quickstep_iterations > kMaxQuickStepIterations) {
      physics.at("quickstep_iterations")
          .fail("must be between 1 and " + std::to_string(kMaxQuickStepIterations));
    }
  });
  errors.check([&] {
    rollout.quickstep_w = physics.get_double("quickstep_w", rollout.quickstep_w);
    if (!(rollout.quickstep_w > 0.0 && rollout.quickstep_w < 2.0)) {
      physics.at("quickstep_w").fail("must be in (0, 2) (SOR over-relaxation)");
    }
  });
  errors.check([&] {
    const double seed = physics.get_double("quickstep_seed", rollout.quickstep_seed);
    if (!(seed >= 0.0 && seed <= 4294967295.0 && std::floor(seed) == seed)) {
      physics.at("quickstep_seed").fail("must be a whole number from 0 to 4294967295");
    }
    rollout.quickstep_seed = static_cast<std::uint32_t>(seed);
  });
  errors.check([&] { read_flex_model(physics, rollout); });
  errors.check([&] {
    rollout.max_contacts_per_foot = physics.get_int("max_contacts", rollout.max_contacts_per_foot);
    if (rollout.max_contacts_per_foot < 1 || rollout.max_contacts_per_foot > 64) {
      physics.at("max_contacts").fail("must be between 1 and 64");
    }
  });
  errors.check([&] {
    rollout.gear_substeps = physics.get_int("gear_substeps", rollout.gear_substeps);
    if (rollout.gear_substeps < 1 || rollout.gear_substeps > kMaxGearSubsteps) {
      physics.at("gear_substeps").fail("must be between 1 and " + std::to_string(kMaxGearSubsteps));
    }
  });
  errors.check([&] {
    structure.flex_sub_bodies = physics.get_int("flex_sub_bodies", structure.flex_sub_bodies);
    if (structure.flex_sub_bodies < 1 || structure.flex_sub_bodies > 16) {
      physics.at("flex_sub_bodies").fail("must be between 1 and 16");
    }
  });
  errors.check([&] {
    structure.universal_joints = physics.get_bool("universal_joints", structure.universal_joints);
  });
  errors.check([&] {
    rollout.settle_s = physics.get_double("settle_s", rollout.settle_s);
    if (!(rollout.settle_s >= 0.0 && rollout.settle_s <= kMaxSettle_s)) {
      physics.at("settle_s")
          .fail("must be between 0 and " + std::to_string(int(kMaxSettle_s)) + " s");
    }
  });
  errors.check([&] { rollout.hold_torso = physics.get_bool("hold_torso", rollout.hold_torso); });
  errors.check([&] { rollout.float_state = physics.get_bool("float_state", rollout.float_state); });
  errors.throw_if_any();
}

}  // namespace

ScenarioPhysics read_scenario_physics(const std::optional<YamlValue>& physics,
                                      const ScenarioOverrides& overrides) {
  ScenarioPhysics out;
  if (physics) read_physics_section(*physics, out);
  for (const YamlValue& section : overrides.physics) read_physics_section(section, out);
  if (overrides.solver) out.rollout.solver = *overrides.solver;
  if (overrides.flex_sub_bodies) out.structure.flex_sub_bodies = *overrides.flex_sub_bodies;
  if (overrides.gear_substeps) out.rollout.gear_substeps = *overrides.gear_substeps;
  if (overrides.universal_joints) out.structure.universal_joints = *overrides.universal_joints;
  if (overrides.settle_s) out.rollout.settle_s = *overrides.settle_s;
  return out;
}

}  // namespace detail
}  // namespace motoflex
