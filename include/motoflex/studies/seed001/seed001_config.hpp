#pragma once

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/io/yaml_reader.hpp"

namespace motoflex {

// The experiments of seed 001's Section 5 as a YAML file (scenarios/experiments/seed001.yaml):
// which walks to run, under which model variants, and the ZMP experiment.
//
//   walks:                             # each a scenario whose motion is a `walk`
//     - {name: walk_200_1, scenario: ../walks/nao_walk_200_1.yaml, figure: pitch}
//     - {name: walk_50_2, scenario: ../walks/nao_walk_50_2.yaml, figure: roll}
//     # a walk for some of the variants only (by default it runs under every one):
//     - {name: walk_50_2_dortmund, scenario: seed001/walk_50_2_dortmund.yaml,
//        variants: [rigid_2011, ext_2011]}
//     # or a command file replayed as it is (a 2011 MoToFlex command file or a joint log):
//     - {name: commands_200_1, commands: UncompensatedTarget200.csv, step_s: 0.5,
//        steady_s: [1.0, 9.0], figure: pitch}
//   variants:                          # each a scenario or truth file (robot, servo, physics,
//     - {name: rigid, scenario: seed001/rigid.yaml}            #   parameters); its own motion,
//     - {name: ext_physical, scenario: ../truth/nao_motoflex.yaml, params: fitted.json}
//     - {name: ext_2011, pending: "why it cannot run yet"}     #   if any, is replaced by the walk
//     # physics keys set on top of the scenario's (ScenarioOverrides::physics):
//     - {name: ext_2011_float, scenario: ../truth/nao_motoflex_2011.yaml,
//        physics: {float_state: true}}
//   zmp:                               # the reference-ZMP experiment (seed 001 §5, last para.)
//     walk: walk_50_2                  # one of the walks
//     search:                          # numeric walk options (NaoWalkParams) and the values
//       zmp_offset_y_m: [0.03, 0.01]   #   tried: one trial per value, every other option as
//       zmp_transfer_smoothing: [1]    #   the walk file has it
//     variants: [ext_physical]         # the models it is searched for (pending ones skipped)
//
// Paths are relative to the file. A variant's walk is planned for the variant's robot.
struct Seed001Walk {
  std::string name;
  std::string scenario_path;  // a walk of our planner (empty for a command file)
  std::string commands_path;  // a command file replayed instead (empty for a planned walk)
  std::string figure;         // "pitch" (seed 001 Fig. 3), "roll" (Fig. 4) or "" (no figure)
  // The variants it runs under (`variants: [...]`, e.g. the robots it can be planned for);
  // empty: every variant.
  std::vector<std::string> variants;
  bool runs_under(const std::string& variant) const {
    return variants.empty() ||
           std::find(variants.begin(), variants.end(), variant) != variants.end();
  }
  // A command file has no plan to take these from: one step (half a gait cycle) and the window
  // of the steady speed (default: motoflex_2011.md §1's 1 s to 9 s).
  double step_s = 0.0;
  double steady_start_s = 1.0;
  double steady_end_s = 9.0;
  bool replays_commands() const { return !commands_path.empty(); }
};

struct Seed001Variant {
  std::string name;
  std::string scenario_path;         // empty when pending
  std::string params_path;           // optional parameter JSON applied on top
  std::optional<YamlValue> physics;  // optional `physics:` keys applied on top
  std::string pending;               // non-empty: not runnable yet, and why
};

// One setting the ZMP experiment tries: walk option `option` at `value`.
struct Seed001ZmpSetting {
  std::string option;
  double value = 0.0;
};

struct Seed001ZmpSearch {
  std::string walk;                         // empty: no ZMP experiment
  std::vector<Seed001ZmpSetting> settings;  // in the file's order
  std::vector<std::string> variants;
};

struct Seed001Config {
  std::string path;
  std::vector<Seed001Walk> walks;
  std::vector<Seed001Variant> variants;
  Seed001ZmpSearch zmp;
};

// Throws InputError naming file, line and field for a missing, unknown or ill-typed key, a
// duplicate name, a figure other than pitch/roll, a ZMP option that is not a numeric walk key,
// or a ZMP walk or variant that is not listed.
Seed001Config load_seed001_config(const std::string& path);

// Sets the command file of the command-file walk `name` (`motoflex experiment --commands
// NAME=FILE`); InputError when no such walk is listed or it is a planned walk.
void set_walk_command_file(Seed001Config& config, const std::string& name, const std::string& path);

// The config file `motoflex experiment NAME` runs: NAME itself when it is an existing file,
// else <data directory>/scenarios/experiments/NAME.yaml (InputError when neither exists).
std::string find_experiment_config(const std::string& name);

}  // namespace motoflex
