#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/motion/nao_walk.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {

// One simulation set-up read from a scenario YAML: which robot, how it is simulated, what it is
// commanded to do, and parameter values on top of the robot's defaults.
//
//   name: nao_default            # optional, defaults to the file stem
//   robot: robots/nao            # folder with robot.yaml, relative to this file
//   servo: motoflex              # optional; the robot's default otherwise
//   seed: 1                      # sensor-noise stream
//   physics: {dt_s: 0.001, solver: step, quickstep_iterations: 20, quickstep_w: 1.3,
//             quickstep_seed: 0,
//             gear_substeps: 100, flex_sub_bodies: 1, flex_model: implicit, max_contacts: 4,
//             universal_joints: true, settle_s: 0.5, hold_torso: false, float_state: false}
//            # flex_model: implicit | explicit_cfm (FlexModel, rollout.hpp); max_contacts: per
//            # foot box and step; quickstep_w: SOR factor of solver: quick; quickstep_seed:
//            # ODE's random state at its first step (the rows' shuffle; 0 = a fresh process's);
//            # float_state: the bodies' state rounded to single precision after each step (the
//            # 2011 program's)
//   motion:                      # exactly one of:
//     log: ../reference_data/walk.csv        # replay the .cmd columns of a joint log
//     keyframes: {rate_hz: 100, frames: [{t_s: 0, pose: {LKneePitch: 0.5}}, ...]}
//     stand: {duration_s: 5, rate_hz: 100}   # hold the robot's stand pose
//     walk: {speed_mm_s: 100, step_duration_s: 1}  # Nao walk / kick; options in
//     kick: {kick_leg: right}                #   src/scenario/nao_scenario_motion.hpp
//     titan_crawl: {posture: A, periods: 3}  # TITAN-VIII motions of seed 000; options in
//     titan_updown: {amplitude_m: 0.03}      #   src/scenario/titan_scenario_motion.hpp
//     titan_stand: {duration_s: 5}
//   parameters: {motor.R_ohm: 6.5}           # overrides
struct Scenario {
  std::string path;
  std::string name;
  std::shared_ptr<const RobotModel> model;
  ParameterSet parameters;
  RolloutOptions rollout;
  CommandTrajectory commands;
  double log_rate_hz = 100.0;
  std::string motion_description;
  // Per-log parameters of a replayed log's sidecar (experimental conditions such as a bench's
  // mass and gain); they are already applied to `parameters` and travel on into logs recorded
  // from this scenario.
  std::map<std::string, double> log_parameters;
  // The plan behind a `walk` motion (footsteps, reference ZMP, steady window); null otherwise.
  std::shared_ptr<const NaoWalkPlan> walk_plan;
};

// Command-line replacements applied while loading (they win over the file).
struct ScenarioOverrides {
  std::optional<std::string> motion_log;  // --motion LOG.csv
  // The `motion:` section of this scenario file instead of the scenario's own (its relative
  // paths resolve against that file); the motion is planned for the scenario's robot.
  std::optional<std::string> motion_scenario;
  // Replace these numeric keys of a `walk` motion (e.g. zmp_offset_y_m); an InputError names a
  // key that is not one.
  std::map<std::string, double> walk_options;
  std::optional<std::string> parameters_json;  // --params P.json
  bool allow_out_of_bounds = false;            // --allow-out-of-bounds (for parameters_json)
  // `physics:` sections read on top of the scenario's in this order (a truth file's, then e.g.
  // an experiment variant's), before the single overrides below.
  std::vector<YamlValue> physics;
  // A `robot:` value used instead of the scenario's (a truth file's; its path resolves against
  // the file it was written in).
  std::optional<YamlValue> robot;
  std::optional<StepSolver> solver;  // --solver step|sparse|quick
  std::optional<std::string> servo;  // --servo (a servo law's name)
  std::optional<int> flex_sub_bodies;
  std::optional<int> gear_substeps;
  std::optional<bool> universal_joints;
  std::optional<double> settle_s;
  std::optional<double> duration_s;  // truncate the motion
  bool motion_optional = false;      // a scenario without `motion` is accepted (fits bring logs)
};

// Throws InputError naming file, line and field for anything wrong in the scenario, the robot,
// the motion log or the parameter file.
Scenario load_scenario(const std::string& path, const ScenarioOverrides& overrides = {});

// "step", "sparse" or "quick"; nullopt for anything else, which a caller reports with
// kStepSolverChoices.
std::optional<StepSolver> parse_step_solver(const std::string& text);
inline constexpr const char* kStepSolverChoices = "expected 'step', 'sparse' or 'quick'";

// Reads a `physics:` section's `dt_s` (in (0, 0.01] s) and `solver` (step | sparse | quick) into
// `rollout`, leaving what is absent; throws InputError naming the key otherwise. The caller
// checks which other keys the section may have.
void read_step_settings(const YamlValue& physics, RolloutOptions& rollout);

}  // namespace motoflex
