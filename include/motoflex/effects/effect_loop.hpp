#pragma once

// `motoflex loop`: fit the base model → rank the effects that could explain its residual →
// refit the top candidates, each warm-started from the current fit → add the one that lowers the
// validation error significantly (and wins on a validation BIC that charges its extra
// parameters) → repeat until nothing helps or the iteration limit. Every fit is an ordinary run
// dir below the loop's out dir (00_base, 01_<effect>, ...), so a killed loop resumes where it
// stopped when run again with the same arguments.

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "motoflex/effects/effect_signature.hpp"
#include "motoflex/fit/fit_config.hpp"

namespace motoflex {

// An IMU error where the logs have no IMU columns.
inline constexpr double kNoImu = std::numeric_limits<double>::quiet_NaN();

struct LoopRefit {
  std::string effect;
  std::string run_dir;
  double train_rms_deg = 0.0;
  double val_rms_deg = 0.0;
  double val_mae_rad = 0.0;
  double val_imu_rms_deg = kNoImu;  // torso roll and pitch together, when the logs have them
  double val_bic = 0.0;
  std::size_t free_parameters = 0;
  std::uint64_t evaluations = 0;
  double seconds = 0.0;
  bool significant = false;  // passes the gain and BIC tests: the effect is credited
  // The effect does not help at the refit's optimum: with its parameters back at the current
  // model's (neutral) values the training fitness is no worse (a Stribeck term fitted to 0 N·m,
  // a current limit above every current; inert_effect.hpp). Such a refit only re-optimised the
  // model's own parameters: it is never significant.
  bool inert = false;
  // A control that passes the tests against the current model, or an inert refit whose values
  // without the effect (NN_reoptimised_<effect>) do: a candidate for going on re-optimised when
  // no effect is credited.
  bool reoptimises = false;
};

struct LoopIteration {
  std::string model_run_dir;  // the fit whose residual was ranked
  EffectRanking ranking;
  std::vector<LoopRefit> refits;
  std::string added_effect;  // empty: nothing helped; "discovered_torque": discovered terms
  // No effect was added, but a re-optimisation of the current model (the control refit, or an
  // inert effect's refit with the effect dropped, run dir NN_reoptimised_<effect>) passed the
  // validation tests: the loop went on from it (LoopOptions::control).
  bool reoptimised = false;
  std::string reoptimised_from;  // the refit row it came from ("control" or the inert effect)
  // When no library effect helped and discovery ran: what it proposed (formula with the
  // linearised estimates), its score, and the refit's formula when it was added.
  std::string discovery_proposal;
  double discovery_explained = 0.0, discovery_delta_bic = 0.0;
  std::string discovered_formula;
  nlohmann::json fitted;  // free parameter → value of the fit after this iteration
  double train_rms_before_deg = 0.0, train_rms_after_deg = 0.0;
  double val_rms_before_deg = 0.0, val_rms_after_deg = 0.0;
  double val_mae_before_rad = 0.0, val_mae_after_rad = 0.0;
  double val_imu_rms_before_deg = kNoImu, val_imu_rms_after_deg = kNoImu;
  double ranking_seconds = 0.0;
};

struct LoopResult {
  std::string out_dir;
  std::vector<std::string> base_model;   // effects whose parameters the base fit frees
  std::vector<std::string> final_model;  // base model + added effects
  std::string base_run_dir, final_run_dir;
  std::vector<LoopIteration> iterations;
  std::uint64_t evaluations = 0;     // of every fit the loop ran (from their summaries)
  std::uint64_t probe_rollouts = 0;  // signature probes and the refits' start checks
  double fit_seconds = 0.0;          // sum of the fits' own wall times
  double wall_seconds = 0.0;         // this invocation
  // Non-empty when the base fit did not converge and the loop was forced on: why every
  // iteration's ranking is unreliable.
  std::string unreliable_reason;
};

// Runs the loop of the fit config at `fit_path` (with its `loop:` options) into its out dir and
// writes loop.json and report.md (with PNG plots) there. Throws InputError when the config has
// no validation logs (the loop decides on them), and when the base fit did not converge unless
// `force` (then every ranking is marked unreliable; see convergence_guard.hpp). With
// `loop.control` every iteration also refits the current model alone, and an effect must beat
// that control too (see LoopOptions::control).
LoopResult run_loop(const std::string& fit_path, const FitOverrides& overrides, bool force = false);

}  // namespace motoflex
