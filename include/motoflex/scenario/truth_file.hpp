#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/scenario/scenario.hpp"

namespace motoflex {

// A truth file: the model behind synthetic "measured" logs (`motoflex record`), e.g.
// scenarios/truth/nao_motoflex.yaml. Fitting never reads one.
//
//   name: nao_motoflex
//   seed: 7                            # sensor-noise streams (one per recording, see below)
//   digits: 9                          # significant digits of recorded angles (0: exact)
//   robot: ../robots/nao_motoflex_2011 # optional: replaces each scenario's robot (the motions
//                                      #   are planned for it)
//   servo: motoflex                    # optional: replaces each scenario's servo
//   physics: {flex_sub_bodies: 2, gear_substeps: 100, settle_s: 0.5}   # optional: any key of
//                                      #   a scenario's physics, on top of each scenario's
//   parameters: {sensor.resolution_bits: 12, motor.R_ohm: 6.6}         # the truth values
//   recordings:
//     - {name: train/walk, scenario: ../walks/nao_walk_50_2.yaml, parameters: {...}}
struct TruthRecording {
  std::string name;           // output name below the record folder, e.g. "train/walk_050mm_2s"
  std::string scenario_path;  // resolved against the truth file
  std::optional<YamlValue> parameters;  // this recording's own truth values, if any
};

struct TruthFile {
  std::string path;
  std::string name;
  int seed = 1;
  int digits = 0;
  ScenarioOverrides overrides;          // the truth's robot, servo and physics
  std::optional<YamlValue> parameters;  // the truth values for every recording
  std::vector<TruthRecording> recordings;
};

// True when `path` is a YAML mapping with a `recordings` key (a truth file, not a scenario).
// False for anything unreadable (the scenario loader then reports the problem).
bool is_truth_file(const std::string& path);

// Throws InputError naming file, line and field for a missing or ill-typed key, an unknown key,
// a bad recording name (absolute or with '..') or no recordings.
TruthFile load_truth_file(const std::string& path);

// The scenario of recording `index` as `motoflex record` simulates it: loaded with the truth's
// robot, servo and physics overrides (then `extra`'s, which win), the truth's and the recording's
// parameters applied on top (then `extra.parameters_json`, which wins), and the sensor-noise seed
// of that recording, mix64(seed · 0x100000001B3 + index). Throws InputError for a parameter the
// robot does not have.
Scenario truth_recording_scenario(const TruthFile& truth, std::size_t index,
                                  const ScenarioOverrides& extra = {});

// Index of the recording called `name`; InputError listing the names when there is none.
std::size_t truth_recording_index(const TruthFile& truth, const std::string& name);

// load_scenario for a scenario file; for a truth file the scenario of its recording `recording`
// (the first when empty) with the truth applied, as above. What `motoflex simulate` and the
// seed-001 experiment load, so that a truth model can be simulated on any motion.
Scenario load_scenario_or_truth(const std::string& path, const ScenarioOverrides& overrides = {},
                                const std::string& recording = "");

}  // namespace motoflex
