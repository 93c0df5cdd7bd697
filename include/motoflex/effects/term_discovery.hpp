#pragma once

// Open-ended effect discovery (SINDy-style): when no library effect explains the residual of a
// fit, look for a sparse combination of candidate joint torques (torque_terms.hpp: position
// error, velocity, sign of velocity, the gravity load, low powers and products, periodic
// functions of the angle) that does. Each candidate's coefficient is probed once (all joints at
// once, its response shared out per joint as in effect_signature.hpp), which gives the
// sensitivity of the simulated encoders to that torque — the linearised residual. The residual
// is regressed on those columns together with the fit's own Jacobian (so a term is credited only
// with what re-tuning the fit's parameters cannot explain), and sequentially thresholded least
// squares over a path of thresholds proposes sparse supports (plus every single candidate).
// The linearised fit ranks them by ΔBIC (N_eff·ln RSS₁/RSS₀ + k·ln N_eff, as the ranking's), but
// on a smooth residual N_eff is a handful of samples and collinear candidates fit about equally,
// so rollouts decide: the support whose terms, at their linearised estimates (with the fit's
// parameters kept or moved by the same step), lower the training fitness most, by at least 5 %,
// wins. The loop then refits the model with those coefficients free and keeps them only if the
// validation tests pass.

#include <string>
#include <utility>
#include <vector>

#include "motoflex/fit/fit_config.hpp"
#include "motoflex/model/effect_library.hpp"

namespace motoflex {

struct DiscoveredTerm {
  std::string parameter;  // joint.<J>.term_<leaf>
  std::string joint;
  std::string formula;    // φ, e.g. "ω·|ω|"
  double estimate = 0.0;  // linearised coefficient
};

struct TermDiscovery {
  std::vector<DiscoveredTerm> terms;  // the selected support; empty: nothing supported
  double explained = 0.0;             // 1 − RSS₁/RSS₀ of the support (beyond the fit's own)
  double delta_bic = 0.0;
  std::size_t candidates = 0;  // candidate columns (term × joint)
  std::size_t probe_rollouts = 0;
  // Warm start of the refit: model parameter → value (terms), free parameter → value (fit).
  std::vector<std::pair<std::string, double>> estimate;
  std::vector<std::pair<std::string, double>> fit_start;
};

// Discovers at most `max_terms` terms for the fit `config` at `current` on its training logs.
// Terms whose parameter the fit already frees are not candidates. `screen` > 0 refines the
// `screen` best supports by ΔBIC (each with a few Levenberg–Marquardt iterations on rollouts,
// its coefficients and the fit's parameters together: support_refinement.hpp) before they are
// compared, then by the ΔBIC of their training fitness; 0 keeps the first-order estimates.
// Deterministic for any thread count.
TermDiscovery discover_terms(const FitConfig& config, const ParameterSet& current, int threads,
                             std::size_t max_terms, std::size_t screen = 0);

// The effect that frees the discovered terms' coefficients (not in the library; its name is
// "discovered_torque").
Effect discovered_effect(const std::vector<DiscoveredTerm>& terms);

// "τ_<joint> = c₁·φ₁ + c₂·φ₂" per joint, coefficients from `values` (model parameter values).
std::string discovered_formula(const std::vector<DiscoveredTerm>& terms,
                               const ParameterSet& values);

}  // namespace motoflex
