#pragma once

#include <optional>
#include <string>
#include <vector>

#include "motoflex/sim/rollout.hpp"
#include "motoflex/studies/seed001/seed001_config.hpp"
#include "motoflex/studies/seed001/walk_metrics.hpp"

namespace motoflex {

// What one walk did under one model variant: seed 001 §5's numbers (definitions in the README,
// "Seed 001's experiments") and the torso series behind them. NaN marks a number that does not
// exist for this run (no fall, a steady part too short to measure).
// One replica of a run: the same walk and model with every commanded angle perturbed by a
// tiny seeded noise (Seed001Ensemble). A walk whose outcome moves with such a perturbation is
// chaotic there, and its single run is one draw of a distribution.
struct Seed001Replica {
  bool fell = false;
  double fall_s = 0.0;  // NaN when it did not fall
  double speed_mm_s = 0.0;
  double mean_speed_mm_s = 0.0;
  double lateral_m = 0.0;
};

struct Seed001Run {
  std::string walk;
  std::string variant;
  std::string pending;      // non-empty: the variant cannot run yet (nothing else is set)
  std::string unplannable;  // non-empty: the planner cannot plan this walk (ZMP trials only)

  RolloutEnd end = RolloutEnd::kCompleted;
  double end_time_s = 0.0;
  std::string end_detail;
  // The steady part of the walk (plan: end of the first full step to the start of the closing
  // step), cut to the last step boundary before a fall.
  double steady_start_s = 0.0;
  double steady_end_s = 0.0;
  double step_s = 0.0;           // one step: half a gait cycle
  double speed_mm_s = 0.0;       // torso CoM forward travel over the steady part / its time
  double mean_speed_mm_s = 0.0;  // the same from 1 s to min(9 s, end) (motoflex_2011.md §1)
  double distance_m = 0.0;       // torso CoM forward travel, start to end
  double lateral_m = 0.0;        // torso CoM sideways travel (+y left), start to end
  bool fell = false;             // ended by a fall (or a divergence)
  double fall_s = 0.0;           // NaN when it did not fall
  std::optional<FallDirection> fall_direction;
  double fall_roll_rad = 0.0;  // torso tilt at the last frame before the fall
  double fall_pitch_rad = 0.0;
  double pitch_alternation = 0.0;        // alternation_ratio of the per-step torso pitch ranges
  double pitch_range_rad = 0.0;          // mean per-step torso pitch range (steady part)
  double max_abs_roll_rad = 0.0;         // largest |torso roll| before the end
  RolloutResult result;                  // frames, torso position, IMU roll/pitch
  std::vector<Seed001Replica> ensemble;  // empty unless an ensemble was asked for
  // Replicas with the quick step's rows in another order (Seed001Ensemble::quickstep_seeds);
  // empty unless asked for and the variant steps with solver: quick.
  std::vector<Seed001Replica> seed_ensemble;
};

// Replicas of every walk run (not of the ZMP trials): `size` runs each, replica k with its
// commands plus N(0, sigma_rad²) noise drawn from the stream {k, hash of walk and variant}; and
// for a variant with solver: quick, `quickstep_seeds` runs more, replica k with the commands as
// they are and physics.quickstep_seed k (1..quickstep_seeds; the run itself has 0): the same
// model with the quick step's rows shuffled in another order.
struct Seed001Ensemble {
  int size = 0;
  double sigma_rad = 1e-7;
  int quickstep_seeds = 0;
};

// One trial of the ZMP experiment: the walk with one setting under one variant. A value the
// walk planner cannot plan (e.g. beyond a joint limit) is a trial too, marked unplannable.
struct Seed001ZmpTrial {
  Seed001ZmpSetting setting;
  Seed001Run run;
};

struct Seed001ZmpResult {
  std::string walk;
  // The walk's own value of every searched option (the file's, or the planner's default).
  std::vector<Seed001ZmpSetting> defaults;
  std::vector<std::string> variants;
  std::vector<std::vector<Seed001ZmpTrial>> trials;  // [variant][setting], config order
  // Per variant: index of the trial choose_zmp_trial picks, −1 when every trial fell.
  std::vector<int> chosen;
};

struct Seed001Results {
  std::vector<Seed001Run> runs;  // walk-major, variants in config order
  std::optional<Seed001ZmpResult> zmp;
  double wall_s = 0.0;
};

// Runs every walk under every variant (pending variants are listed, not run) and the ZMP
// search, `threads` rollouts at a time (results do not depend on it). Throws InputError for a
// bad scenario, a walk scenario whose motion is not a `walk`, or a ZMP option that is not a
// numeric walk key.
Seed001Results run_seed001(const Seed001Config& config, int threads,
                           const Seed001Ensemble& ensemble = {});

// The metrics of a finished rollout of a planned walk (steady window and step from the plan).
Seed001Run evaluate_walk_run(RolloutResult result, double steady_start_s, double steady_end_s,
                             double step_s);

// The trial chosen from a variant's trials: among those that walked to the end without
// falling, the one with the smallest max_abs_roll_rad (the widest margin against the sideways
// fall of seed 001's second experiment; ties: the earlier in the search order); −1 when none.
int choose_zmp_trial(const std::vector<Seed001ZmpTrial>& trials);

}  // namespace motoflex
