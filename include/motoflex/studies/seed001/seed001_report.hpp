#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "motoflex/studies/seed001/seed001_config.hpp"
#include "motoflex/studies/seed001/seed001_study.hpp"

namespace motoflex {

// seed001.json: {"<walk>": {"<variant>": {speed_mm_s, fell, fall_s, fall_direction,
// pitch_alternation, ...} | {"pending": why}}, ..., "zmp_experiment": {...}, "figures": {...}}.
// Numbers that do not exist for a run (no fall, no steady part) are null. No wall-clock times:
// the same inputs give the same bytes.
nlohmann::ordered_json seed001_json(const Seed001Config& config, const Seed001Results& results);

// Writes DIR/seed001.json, the torso series of every run (DIR/series/<walk>__<variant>.csv and
// DIR/series/zmp__<variant>__<value>.csv: time_s, torso_x_m, torso_y_m, torso_z_m, roll_rad,
// pitch_rad), and with `plots` the figures in the style of seed 001's Fig. 3 and 4 and of the
// ZMP search (scripts/plot_seed001.py; a failed plot is a warning). Throws InputError when a
// file cannot be written.
void write_seed001_report(const Seed001Config& config, const Seed001Results& results,
                          const std::string& out_dir, bool plots);

}  // namespace motoflex
