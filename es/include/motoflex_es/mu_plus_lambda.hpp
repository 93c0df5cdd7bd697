#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "motoflex_es/strategy.hpp"

namespace motoflex_es {

// How an offspring's object parameters (x) or step sizes are formed from its ρ parents.
enum class Recombination {
  kNone,          // copied from the first of the chosen parents
  kDiscrete,      // each coordinate from a parent chosen uniformly among the ρ ("dominant")
  kIntermediate,  // each coordinate the arithmetic mean over the ρ parents
};
const char* to_string(Recombination recombination);

// κ for plus selection: no parent ever becomes too old to be kept.
inline constexpr std::uint64_t kUnlimitedLifetime = std::numeric_limits<std::uint64_t>::max();

// Options of the (μ, κ, λ, ρ)-ES. Defaults follow seed 001 §4: a (10+800)-ES with a maximum
// lifetime of 3 generations; ρ and the recombination types are not given there and use
// Schwefel's classic choice (discrete for x, intermediate for the step sizes).
struct MuPlusLambdaOptions {
  // μ: parents kept after each selection.
  std::size_t mu = 10;
  // λ: offspring per generation; at least μ.
  std::size_t lambda = 800;
  // κ: maximum lifetime. A parent enters the next selection only while its age (selections it
  // has passed) is below κ, so no individual is ever older than κ. κ = 1 is comma selection
  // (μ,λ); kUnlimitedLifetime is plus selection (μ+λ), which keeps the best ever found.
  std::uint64_t kappa = 3;
  // ρ: parents per offspring, 1..μ, chosen uniformly without replacement.
  std::size_t rho = 2;
  Recombination object_recombination = Recombination::kDiscrete;
  Recombination step_recombination = Recombination::kIntermediate;
  // Log-normal self-adaptation σ_i ← σ_i·exp(τ'·N(0,1) + τ·N_i(0,1)) with one N(0,1) per
  // offspring and one N_i(0,1) per coordinate. 0 selects τ' = 1/√(2n) and τ = 1/√(2√n)
  // (Schwefel 1995; Beyer & Schwefel 2002).
  double tau_global = 0.0;
  double tau_local = 0.0;
  // Initial population: start_point itself plus μ−1 points drawn around it with the initial step
  // sizes (reflected into the bounds); all μ uniform in the bounds if empty.
  std::vector<double> start_point;
  // Initial step size of every coordinate as a fraction of that coordinate's bound width.
  double initial_step_relative = 0.1;
  // Every step size is kept within [floor, ceiling]·width after mutation. The floor stops the
  // self-adaptation from collapsing (a step far below what the fitness can resolve never
  // recovers); beyond one width a reflected step is as good as uniform, hence the ceiling.
  double step_floor_relative = 1e-12;
  double step_ceiling_relative = 1.0;
  // Stop once the best fitness is <= this.
  double target_fitness = -std::numeric_limits<double>::infinity();
  // Stop after this many generations without a strict improvement of the best; 0 = never.
  std::uint64_t max_stagnation_generations = 0;
  // Stop once every step size of every parent is below this fraction of its width; 0 = never.
  double tol_step_relative = 0.0;
  // Keys every random stream of the run.
  std::uint64_t seed = 1;
  // Racing within a generation (below): each offspring is also judged against the offspring
  // evaluated before it. Off: against the parents alone. Bit-identical either way; only the
  // work differs, so it is not part of a checkpoint's identity.
  bool racing = true;
  // Offspring per racing chunk after the first μ; 0 = μ. A chunk waits for its slowest rollout,
  // so with more workers (threads × ranks) than μ set it to the number of workers: none then
  // waits idle for want of work. The run's state does not depend on it; what stopped offspring
  // report (the censored batch median) does, which is why it is the run's setting and not the
  // evaluator's width.
  std::size_t race_chunk = 0;

  // True if the options are consistent; otherwise false and a one-line reason in *why.
  // (Whether start_point fits the bounds is checked by the MuPlusLambda constructor.)
  bool is_valid(std::string* why) const;
};

// One member of the parent population.
struct Individual {
  std::vector<double> x;                                     // object parameters, within the bounds
  std::vector<double> step;                                  // σ_i, in the units of x_i
  double fitness = std::numeric_limits<double>::infinity();  // NaN stored as +inf
  // Selections survived: 1 when first selected as an offspring (or for the initial population),
  // +1 for every later selection it survives; never more than κ.
  std::uint64_t age = 0;
};

// The (μ, κ, λ, ρ)-ES of Schwefel & Rudolph (1995) with individual, self-adaptive step sizes.
// Generation 0 asks for the μ initial individuals; every later generation asks for λ
// offspring, each recombined from ρ random parents and mutated (step sizes first, then x with
// the new step sizes, then reflected into the bounds). Selection keeps the μ best of the λ
// offspring and the parents whose age is below κ; among equal fitness a parent wins over an
// offspring and an earlier one over a later one.
// Early termination: selection_threshold() is the μ-th best fitness among the parents that
// will compete in the next selection (+inf while fewer than μ can). An offspring whose fitness
// is >= it lands behind μ parents and is never selected, and it cannot beat the best so far, so
// any reported value >= the threshold leaves the run unchanged.
// Racing within a generation: only the μ best of the pool are kept, so exact_ranks_needed() is
// μ, and race_threshold() is the μ-th best of the competing parents together with the offspring
// evaluated so far (earlier in the batch: they win ties, as the parents do). Each chunk of μ
// offspring evaluated tightens the bound for the rest of the batch; on the (10+800)-ES the bound
// soon sits at the best 10 of several hundred. The chunks are μ (or options().race_chunk)
// whatever the evaluator's width, because the batch median in a fit's progress may be a stopped
// offspring's partial value: so it, too, is the same for any number of threads or ranks.
class MuPlusLambda final : public Strategy {
 public:
  // Throws std::invalid_argument for invalid options or a start point of the wrong size or
  // outside the bounds.
  MuPlusLambda(Bounds bounds, MuPlusLambdaOptions options);

  std::string name() const override { return "mu_plus_lambda"; }
  std::vector<std::vector<double>> ask() override;
  void tell(const std::vector<double>& fitness) override;
  std::size_t next_batch_size() const override;
  double selection_threshold() const override;
  std::size_t exact_ranks_needed() const override;
  double race_threshold(const std::vector<double>& exact_sorted) const override;
  std::size_t race_chunk(std::size_t) const override;
  nlohmann::json save_state() const override;
  void load_state(const nlohmann::json& state) override;

  const MuPlusLambdaOptions& options() const { return options_; }
  // The parents, best first (empty before the first tell).
  const std::vector<Individual>& population() const { return population_; }
  // The learning rates in use (defaults resolved).
  double tau_global() const { return tau_global_; }
  double tau_local() const { return tau_local_; }

 private:
  std::vector<Individual> initial_population() const;
  Individual make_offspring(std::uint64_t index) const;
  double clamp_step(double step, std::size_t coordinate) const;
  void select(const std::vector<double>& fitness);
  void check_stop_criteria();
  // Fitness of the parents that will compete in the next selection (age below κ).
  std::vector<double> competing_fitness() const;
  nlohmann::json options_fingerprint() const;

  MuPlusLambdaOptions options_;
  double tau_global_ = 0.0;
  double tau_local_ = 0.0;
  std::vector<Individual> population_;
  std::vector<Individual> pending_;  // the batch of the outstanding ask()
  std::uint64_t last_improvement_generation_ = 0;
};

}  // namespace motoflex_es
