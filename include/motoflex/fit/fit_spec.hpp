#pragma once

// FitSpec: everything a fit is asked to do, as a user writes it (fit.yaml, or built in code by
// a program or the Python module), before any file it names is read. Modelled on Ceres's
// Solver::Options (and named like es/'s option structs): each field carries its default and
// what it does; is_valid() (Ceres's IsValid) says what is
// wrong without touching the disk. `resolve_fit_config` (fit_config.hpp) then loads the
// scenario, robot and logs it names; FitSession (fit_session.hpp) runs it.
//
// The fit.yaml keys map one to one onto the fields (see scenarios/fit/nao_quick.yaml):
//   name: nao_quick
//   scenario: ../nao_fit_base.yaml      # robot, servo, physics (its motion, if any, is unused)
//   data: ../../reference_data/nao/train   # a folder of logs, a file, or a list (or `logs:`)
//   validation: ../../reference_data/nao/validation   # optional, never fitted on
//   free:                               # name or pattern ('*' within a dotted level)
//     motor.R_ohm: {lower: 3, upper: 12, log: true}
//     joint.*.friction_nm: {lower: 0.01, upper: 3, log: true}        # one tied value
//     gear.*.backlash_rad: {lower: 1e-7, upper: 1e-2, each: true}    # one value per match
//   fixed: {motor.stiffness: 0.7}      # values on top of the robot defaults
//   effects: [stribeck, sensor_delay]  # frees each effect's parameters (effect_library.hpp)
//   fitness: {m: 2, error: squared, settle_s: 0.0, weights: {LKneePitch: 2.0}, imu_weight: 0,
//   window_s: 0,
//             early_termination: true}
//   strategy: {kind: mu_plus_lambda, mu: 10, lambda: 40, kappa: 3}
//   (or {kind: cma_es, sigma: 0.2, active: true, negative_weights: ranked | pooled})
//   budget: {generations: 30, evaluations: 2000, seconds: 600}
//   threads: 2
//   seed: 1
//   out: ../../runs/nao_quick
//   polish: {method: lm, max_iterations: 20, jacobian_step: 1e-3, covariance: true}
//   loop: {candidates: 3, widen: 0, max_iterations: 3, min_gain: 0.05, effects: [...],
//          control: true, discover_terms: 0, discover_always: false, discover_screen: 0,
//          refit: {strategy: {kind: cma_es, sigma: 0.1}, budget: {evaluations: 240},
//                  polish: {method: lm}, scan: 0}}

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace motoflex {

// Where a value of a spec was written (for messages); empty for values set in code.
struct SourceRef {
  std::string file;
  int line = 0;
  std::string field;
};

// Which optimiser a fit runs, with its options (the es library's option structs are filled
// from these).
struct StrategyConfig {
  std::string kind = "mu_plus_lambda";  // mu_plus_lambda | cma_es | nlopt
  // mu_plus_lambda (seed 001: mu 10, lambda 800, kappa 3)
  std::size_t mu = 10;
  std::size_t lambda = 40;
  std::uint64_t kappa = 3;  // 0 = unlimited (plus selection)
  std::size_t rho = 2;
  std::string object_recombination = "discrete";    // none | discrete | intermediate
  std::string step_recombination = "intermediate";  // none | discrete | intermediate
  double initial_step = 0.1;                        // relative to each bound width
  // cma_es
  double sigma = 0.25;  // relative to the bound widths
  std::size_t population = 0;
  std::size_t restarts = 9;
  // The active covariance update (worst samples get negative weights). Off: the original rank-μ
  // update, which lets the driver race the worse half of each generation (bit-identical).
  bool active = true;
  // `negative_weights: pooled` (default `ranked`): the active update's worse ranks, from
  // max(μ, ⌊λ/2⌋+1) on, share one negative weight, so the driver can race them too.
  bool pooled_negative_tail = false;
  // mu_plus_lambda and cma_es: racing within a generation (each individual also judged against
  // the ones evaluated before it). Off: only against the threshold from before the generation,
  // to measure what racing saves; the fit is bit-identical either way.
  bool racing = true;
  // mu_plus_lambda: offspring per racing chunk after the first μ (0 = μ); set it to threads ×
  // ranks when they outnumber μ, so that no worker waits for want of work.
  std::size_t race_chunk = 0;
  // nlopt: bobyqa | sbplx | crs2_lm | isres | esch
  std::string algorithm = "bobyqa";
  // optional local polish of the best point after the main strategy (nlopt local algorithm)
  std::string polish;  // "" = none, bobyqa | sbplx
  std::uint64_t polish_evaluations = 0;
};

struct FitBudget {
  std::uint64_t max_generations = 0;  // 0 = no limit
  std::uint64_t max_evaluations = 0;  // 0 = no limit
  double max_seconds = 0.0;           // 0 = no limit
  // Stop the strategy (and go on to the polish) once the best point, the incumbent's included,
  // has not improved by more than stall_relative of itself over stall_evaluations evaluations
  // (motoflex_es::ImprovementStall). 0 = never. A refit that starts at the current model is
  // where it pays: a wide CMA-ES spends its budget on samples far worse than the incumbent.
  std::uint64_t stall_evaluations = 0;
  double stall_relative = 1e-3;
};

// How a finite-difference Jacobian samples each coordinate (PolishSpec::lm_jacobian).
enum class FiniteDifferences { kCentral, kForward };

// The optional least-squares finish after the strategy (the `polish:` section): Levenberg–
// Marquardt (Ceres) on the residual vector √w_j (q_real − q_sim)/√(T^m) of every scored frame and
// channel of the training logs (so its squared norm is the fitness), with a finite-difference
// Jacobian through the rollout (`jacobian: central`, 2p rollout sets, or `forward`, p) in the
// strategy's search coordinates (log where `log: true`), clamped to the bounds. Its result replaces
// the strategy's best only if it lowers the fitness. With `covariance` the summary reports
// σ²(JᵀJ)⁻¹ at the best point (σ² = RSS/(N−p)), 95 % confidence intervals and the correlation
// matrix (also without LM: `method: none`).
struct PolishSpec {
  std::string method;               // "" / "none": no LM; "lm": Levenberg–Marquardt
  std::size_t max_iterations = 20;  // LM iterations (each: one Jacobian, 2p or p rollout sets)
  double jacobian_step = 1e-3;      // finite-difference step, share of each bound width
  // LM's Jacobian: central differences (x ± h, error O(h²), 2p rollout sets) or forward ones
  // (x + h, error O(h), p rollout sets: half the cost of an iteration). The covariance is
  // always central: it is computed once and its intervals should not carry the O(h) error.
  FiniteDifferences lm_jacobian = FiniteDifferences::kCentral;
  bool covariance = true;  // uncertainty at the best point (default on with lm)
  // Points per parameter of the scan along the parameters LM cannot move (zero Jacobian column)
  // after LM ends, LM going on from a scan that lowers F (flat_direction_scan.hpp); 0: none,
  // else >= 3.
  std::size_t flat_scan = 0;
  bool lm() const { return method == "lm"; }
  bool reports_uncertainty() const { return covariance && (lm() || method == "none"); }
};

// What `motoflex loop` does with a fit (the `loop:` section; plain fits ignore it).
struct LoopOptions {
  std::size_t candidates = 3;  // top-ranked effects refit per iteration
  // When none of those passes: refit up to this many more, next in rank, before discovered
  // terms (refit_candidates.hpp); 0 = stop at the first round.
  std::size_t widen = 0;
  std::size_t max_iterations = 3;  // effects added at most
  // A candidate is added only if it lowers the validation error as the fit measures it (over
  // the fitness's channels: the joints, and the IMU when it is scored; RMS for squared errors,
  // the mean |e| with `error: absolute`, ErrorSummary::fit_error_rad) by at least this fraction
  // and its validation BIC (over the same channels and error) beats the current model's.
  double min_gain = 0.05;
  std::vector<std::string> effects;  // candidates considered (empty: the whole library)
  // When no library effect helps: discover at most this many candidate torque terms by sparse
  // regression (term_discovery.hpp) and refit with them; 0 = off.
  std::size_t discover_terms = 0;
  // Discover in every iteration, the terms' refit competing with the library candidates on the
  // validation BIC (a library effect that only half-fits the residual is then not added first).
  bool discover_always = false;
  // Supports (best linearised ΔBIC first) whose coefficients are refined on rollouts before
  // they compete (term_discovery.hpp); 0 = first-order estimates only. Each costs up to
  // 4·(free parameters + terms + 5) passes over the training logs.
  std::size_t discover_screen = 0;
  StrategyConfig refit_strategy;  // the short warm-started refits
  FitBudget refit_budget;
  // A refit's finish (default none): with `lm`, Levenberg–Marquardt from its best point, which
  // is the current model (the refit's incumbent) when the search found nothing better, so the
  // new effect is also tried right next to the model it extends.
  PolishSpec refit_polish;
  // Points per parameter of the new effect scanned for a refit's start (0: none, else >= 3):
  // each of the effect's parameters in turn across its bounds (log-spaced where `log`), the
  // others held, keeping the best on the training logs. A parameter whose neutral value has no
  // effect at all (a current limit far above any current) gives its signature a zero slope, and
  // the linearised start barely moves it; the scan finds where it starts to act.
  std::size_t refit_scan = 0;
  // `refit: {scan_pairs: true}`: an effect with exactly two parameters is scanned on the whole
  // scan × scan grid of the pair instead of one parameter at a time (refit_start_scan.hpp); for a
  // pair where one parameter switches the other on (winding heating's R_th and C). Needs scan.
  bool refit_scan_pairs = false;
  // Refit the current model alone in each iteration too (the control, `NN_control`), with the
  // same strategy, budget and polish as an effect's refit, started as one is: at the linearised
  // step of the model's own parameters (EffectRanking::fit_start). A refit can find a better
  // optimum of the parameters the model already has; without the control that gain is credited
  // to whichever effect was being refit. With it an effect must beat the better of the current
  // model and the control, and when no effect is credited but the control passes the validation
  // tests, the loop goes on from it ("re-optimised", no effect added). (Independently of this
  // switch an effect that does not help at its refit's optimum is never added: inert_effect.hpp.)
  bool control = true;
  LoopOptions() {
    refit_strategy.kind = "cma_es";
    refit_strategy.sigma = 0.1;
    refit_strategy.restarts = 0;
    refit_budget.max_evaluations = 240;
  }
};

// One `free:` entry: a model parameter name or pattern and how it is searched.
struct FreeParameterSpec {
  std::string pattern;          // a name, or '*' within one dotted level, "**" across levels
  std::optional<double> lower;  // default: the robot's bound of the first match
  std::optional<double> upper;
  std::optional<double> start;  // default: the base value (robot default + fixed + scenario)
  bool log_scale = false;       // search log(value)
  bool each = false;            // one free value per matched parameter instead of one tie
  SourceRef where;
};

// A `data:` / `validation:` item: a folder of logs (every *.csv; a folder of BAM JSON logs, in
// it or in its subfolders, is imported into <out>/imported/), or one log file.
struct LogSource {
  std::string path;
  SourceRef where;
};

// Command-line replacements (they win over the file).
struct FitOverrides {
  std::optional<int> threads;
  std::optional<std::uint64_t> seed;
  std::optional<std::uint64_t> max_generations;
  std::optional<std::uint64_t> max_evaluations;
  std::optional<double> max_seconds;
  std::optional<std::string> out;
  std::optional<std::string> data;
  std::optional<std::string> validation;
  // A run's best.json (`--start-from`): every free parameter starts at its value there, and that
  // point is the incumbent (evaluated first), so a fit chained on another never ends worse.
  std::optional<std::string> start_from;
};

struct FitSpec {
  std::string path;                        // the fit.yaml it was read from ("" when built in code)
  std::string name;                        // run name (default: the file stem)
  std::string scenario_path;               // required: robot, servo and physics of every rollout
  std::vector<LogSource> train_data;       // required: the logs fitted on
  std::vector<LogSource> validation_data;  // optional: scored, never fitted on
  std::vector<FreeParameterSpec> free;     // required: what the optimiser searches
  // Values on top of the robot's defaults and the scenario's `parameters`, in order.
  std::vector<std::pair<std::string, double>> fixed;
  std::vector<SourceRef> fixed_where;    // parallel to `fixed`
  std::vector<std::string> effects;      // library effects whose parameters go free
  std::vector<SourceRef> effects_where;  // parallel to `effects`
  // The model this fit extends, as values of its free parameters (model units, by the names of
  // `free`, every one of them): evaluated once before the search, so the result is never worse
  // than it (the loop's refits: the current model with the new effect at its neutral value).
  // Empty: none.
  std::vector<std::pair<std::string, double>> incumbent;
  SourceRef incumbent_where;
  // A run's best.json the search starts from and keeps as its incumbent (`--start-from`; it
  // replaces `incumbent` and the `start` values): each free parameter's value from its "free"
  // entry, else from "parameters" (a parameter the earlier run held), clamped to the bounds.
  std::string start_from;
  // With start_from: hold the free parameters the earlier run identified (its summary.json's
  // confidence_intervals, `"identified": true`) at their best.json values and search only the
  // others (`hold_identified: true`; a chain's later stage on longer windows, README).
  bool hold_identified = false;
  SourceRef hold_identified_where;
  double fitness_m = 2.0;                       // F = Σ error² / T^m (seed 001 eq. 2), m ≥ 0
  double fitness_settle_s = 0.0;                // unscored frames at each log's start
  std::map<std::string, double> joint_weights;  // joint → w_i ≥ 0 (absent: 1)
  SourceRef joint_weights_where;
  double imu_weight = 0.0;        // weight of the torso IMU's roll/pitch errors (0: joints only)
  double window_s = 0.0;          // score only each log's first window_s seconds (0: whole logs)
  bool absolute_error = false;    // fitness.error: absolute (Σ w|e|) instead of squared (Σ w e²)
  bool early_termination = true;  // stop rollouts that cannot beat the selection threshold
  StrategyConfig strategy;
  FitBudget budget;
  PolishSpec polish;  // default: none (nothing after the strategy)
  LoopOptions loop;
  int threads = 1;         // OpenMP threads (results do not depend on it)
  std::uint64_t seed = 1;  // every random number of the run derives from it
  std::string out_dir;     // run folder (default: runs/<name>)
  SourceRef root;          // the file as a whole (for messages about missing keys)

  // Checks what can be checked without reading files (ranges, required fields, option
  // values). Returns false and sets *error to one line saying what is wrong.
  bool is_valid(std::string* error) const;
};

// Reads fit.yaml into a FitSpec, relative paths resolved against its folder, with `overrides`
// applied. Reports every problem of the file at once (InputErrors naming file, line, field).
FitSpec load_fit_spec(const std::string& path, const FitOverrides& overrides = {});

// Applies command-line overrides (--threads, --seed, budget, --out, --data, --validation).
void apply_fit_overrides(FitSpec& spec, const FitOverrides& overrides);

}  // namespace motoflex
