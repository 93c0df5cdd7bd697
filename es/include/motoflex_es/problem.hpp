#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace motoflex_es {

// A box in parameter space: lower[i] < upper[i], both finite, for every coordinate. Every
// strategy here needs finite bounds: step sizes are measured relative to the width, CMA-ES
// searches the box normalised to [0, 1]^n, and NLopt's global algorithms require them.
struct Bounds {
  std::vector<double> lower;
  std::vector<double> upper;

  std::size_t dimension() const { return lower.size(); }
  double width(std::size_t i) const { return upper[i] - lower[i]; }
  // True if both vectors are non-empty and of one size and lower[i] < upper[i] with both
  // finite; otherwise false and, if `why` is given, a one-line reason naming the coordinate.
  bool is_valid(std::string* why) const;
  bool contains(const std::vector<double>& x) const;
};

// Mirrors `value` into [lower, upper] as often as needed (a periodic reflection with period
// 2·(upper − lower)): inside the box it is the identity, just outside it is the mirror image.
// Used by every strategy here instead of clamping (which piles probability mass onto the faces
// and makes the optimum look like a face) or resampling (whose number of draws is unbounded
// and whose distribution is truncated): a reflected Gaussian step is continuous, keeps its
// scale, and costs exactly one draw. lower < upper, both finite.
double reflect_into_bounds(double value, double lower, double upper);

// What a problem learns about the batch it evaluates. One context applies to the whole batch.
struct EvaluationContext {
  // Generation of the strategy that asked for the batch (0 for the first batch).
  std::uint64_t generation = 0;
  // Index of xs[0] within the generation's batch. Evaluators may split a batch into pieces;
  // xs[k] is then individual first_individual + k. A stochastic problem keys its randomness by
  // (generation, first_individual + k), never by the piece, so results do not depend on the
  // number of threads or ranks.
  std::uint64_t first_individual = 0;
  // Early termination. An individual whose fitness is >= stop_threshold cannot be selected, so
  // its exact value does not matter. A problem whose fitness only grows while it is being
  // computed (a sum of nonnegative per-step errors, say) may stop a rollout as soon as its
  // partial fitness reaches stop_threshold and report any value >= stop_threshold (the partial
  // sum, typically). The strategy guarantees that selection, step-size adaptation, the best
  // solution and every later batch are then bit-identical to those of a full evaluation; only
  // statistics of the rejected individuals (mean or median fitness of a batch) change.
  // +inf (the default) means never stop early. NaN is never passed.
  double stop_threshold = std::numeric_limits<double>::infinity();
  // Threads this call may use for its own work: an evaluator with more threads than the batch
  // has individuals (NLopt asks for one point at a time) hands them down, and a problem made
  // of independent parts (the logs of a fit) can evaluate those in parallel. Results must not
  // depend on it.
  int spare_threads = 1;
};

// An optimisation problem: minimise fitness(x) for x within bounds(). The optimiser knows
// nothing else about it.
class Problem {
 public:
  virtual ~Problem() = default;

  virtual std::size_t dimension() const = 0;
  virtual Bounds bounds() const = 0;

  // Writes the fitness of xs[k] to fitness[k]; `fitness` has been resized to xs.size() by the
  // caller. Lower is better; NaN is read as +inf (the worst), so a diverged simulation is a
  // score, not a crash. May throw (the run then stops with that exception).
  // Concurrency: OpenMpEvaluator calls this from several threads at once, each call with its own
  // xs and fitness (a one-individual batch), so an implementation must not mutate shared state
  // without synchronisation. SerialEvaluator passes the whole batch in one call, which a problem
  // may parallelise internally.
  virtual void evaluate_batch(const std::vector<std::vector<double>>& xs,
                              std::vector<double>& fitness, const EvaluationContext& context) = 0;

  // Optional statistics of the evaluations so far: counts that only grow (rollouts stopped
  // early, frames simulated, ...), for reports; they never feed back into the fitness. The
  // MpiEvaluator adds what every worker's replica counted during a batch to the replica on
  // rank 0 through add_counters, so the totals read there equal those of a run in one process.
  // Every replica must return the same number of counters. Default: none.
  virtual std::vector<std::uint64_t> counters() const { return {}; }
  // Adds increments[i] to counter i (increments has counters().size() entries).
  virtual void add_counters(const std::vector<std::uint64_t>& increments) { (void)increments; }
};

}  // namespace motoflex_es
