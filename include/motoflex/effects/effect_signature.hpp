#pragma once

// Which missing effect explains the residual of a fit? For each candidate effect, a probe
// rollout moves the effect's parameter a small step away from the current fit; the change of
// the simulated encoders is the shape the effect would leave in the residual (its signature,
// i.e. a finite-difference column of the model's Jacobian). The residual is regressed on that
// shape (one coefficient per joint or gear group for per-joint effects, one for global ones,
// each coefficient kept within the parameter's bounds); the score is the fraction of the
// residual sum of squares it explains, and ΔBIC = N_eff·ln(RSS₁/RSS₀) + k·ln N_eff decides the
// ranking (negative: the effect is supported by the data despite its k extra coefficients;
// N_eff discounts the residual's autocorrelation, without which a smooth residual of thousands
// of frames would "support" any per-joint effect). The
// regression includes the sensitivities of the fit's own free parameters (one probe each), so
// an effect is credited only with what re-tuning those parameters cannot explain — a base fit
// often half-hides a missing effect by bending K_t or the friction (a Gauss-Newton score test).
// The regression also gives the refit's warm start: the linearised optimum of all parameters.

#include <string>
#include <utility>
#include <vector>

#include "motoflex/fit/fit_config.hpp"

namespace motoflex {

struct EffectScore {
  std::string effect;
  // "scored", or why not: "in model" (its parameters are already free), "held fixed" (the
  // config's `fixed` holds those that are not free), "not applicable", "no parameters",
  // "probe failed: ...".
  std::string status;
  double explained = 0.0;  // 1 − RSS₁/RSS₀
  double delta_bic = 0.0;
  std::size_t coefficients = 0;
  // Warm start: model parameter → value the regression suggests (non-probed parameters keep
  // their current value).
  std::vector<std::pair<std::string, double>> estimate;
  // ... and the fit's own free parameters (free parameter name → value) after the same
  // linearised step: they may have been compensating for the missing effect.
  std::vector<std::pair<std::string, double>> fit_start;
  bool scored() const { return status == "scored"; }
};

struct EffectRanking {
  std::vector<EffectScore> scores;  // scored effects by ΔBIC (best first), then the others
  double rss0_rad2 = 0.0;           // residual sum of squares of the current fit
  std::size_t samples = 0;          // N: scored frames × joints over the training logs
  double effective_samples = 0.0;   // N_eff = N·(1 − ρ)/(1 + ρ), ρ the lag-1 autocorrelation
  std::size_t jacobian_rollouts = 0;  // probes of the fit's own free parameters
  // The fit's own free parameters (name → value) after the linearised step on their own
  // columns, no effect added: the start of the loop's control refit, so that it starts where an
  // effect's refit would with the effect at zero (EffectScore::fit_start).
  std::vector<std::pair<std::string, double>> fit_start;
  // False when the ranked fit did not converge (motoflex residuals/loop --force): its residual
  // mixes a missing effect with the optimiser's unfinished work, so the order may be wrong.
  bool reliable = true;
  std::string unreliable_reason;  // e.g. "the fit did not converge (not converged: budget ...)"
};

// Ranks `candidates` (effect names; empty = the whole library) for the fit `config` at the
// parameter set `current` (in the registry of config's model), on the training logs. Probe
// rollouts run on `threads` threads; the result does not depend on the thread count.
EffectRanking rank_effects(const FitConfig& config, const ParameterSet& current,
                           const std::vector<std::string>& candidates, int threads);

}  // namespace motoflex
