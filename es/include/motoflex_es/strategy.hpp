#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "motoflex_es/problem.hpp"

namespace motoflex_es {

// Why a strategy stopped by itself. The driver adds its own reasons (budget, time, callback).
// The spelling returned by to_string() is part of the checkpoint format.
enum class StopReason {
  kNone,                // still running
  kTargetReached,       // best fitness <= the target fitness of the options
  kTolX,                // the search distribution shrank below the x tolerance
  kTolFun,              // fitness values of recent generations lie within the f tolerance
  kStagnation,          // no progress for the configured number of generations
  kMaxIterations,       // the strategy's own iteration limit (CMA-ES: per restart)
  kConditionNumber,     // CMA-ES covariance condition number above its limit
  kNoEffect,            // CMA-ES: a step along an axis or coordinate no longer changes the mean
  kRestartsExhausted,   // IPOP-CMA-ES: the last permitted restart ended (detail says why)
  kEvaluationBudget,    // the strategy's own evaluation budget cannot fit another batch
  kOptimizerConverged,  // NLopt reported success (detail: which criterion)
  kOptimizerFailed,     // NLopt reported a failure (detail: the message)
  kTolStall,            // CMA-ES: the best fitness improved by less than a relative tolerance
};
const char* to_string(StopReason reason);
// Inverse of to_string; throws CheckpointError for an unknown spelling.
StopReason stop_reason_from_string(std::string_view text);

// The fitness used for ranking: NaN counts as +inf (the worst), everything else as is.
inline double ranked_fitness(double fitness) {
  return fitness != fitness ? std::numeric_limits<double>::infinity() : fitness;
}

// An optimiser with an ask/tell interface (pycma, libcmaes, Nevergrad): the caller owns the loop,
// which makes parallel or distributed evaluation, logging and checkpointing the caller's
// business. One generation is
//   xs = ask();  evaluate xs;  tell(fitness);
// ask() is a pure function of the state (it draws from streams keyed by seed, generation and
// individual), so asking again, or asking after save_state()/load_state(), gives the same batch.
// Minimisation; NaN fitness counts as +inf.
class Strategy {
 public:
  virtual ~Strategy() = default;
  Strategy(const Strategy&) = delete;
  Strategy& operator=(const Strategy&) = delete;

  // Short identifier, also written into the saved state ("mu_plus_lambda", "cma_es", ...).
  virtual std::string name() const = 0;

  // The next batch to evaluate, each point within bounds(). Empty once should_stop().
  virtual std::vector<std::vector<double>> ask() = 0;
  // Fitness of the batch returned by the last ask(), by index. Throws std::logic_error if there
  // is no outstanding ask or the size differs, std::logic_error once stopped.
  virtual void tell(const std::vector<double>& fitness) = 0;
  // Size of the batch the next ask() returns (for budget checks before asking).
  virtual std::size_t next_batch_size() const = 0;

  // The fitness an individual of the next batch must be strictly below to have any influence on
  // the run; +inf if every individual can matter. See EvaluationContext::stop_threshold.
  virtual double selection_threshold() const { return std::numeric_limits<double>::infinity(); }
  // Racing: how many of the next batch's best individuals the strategy must know with their
  // exact fitness and order; every other individual only has to be known to rank below them.
  // The driver then evaluates that many first and the rest against their worst value (see
  // run_optimisation), which changes nothing but the work done. Default: the whole batch.
  virtual std::size_t exact_ranks_needed() const { return next_batch_size(); }
  // Racing within the batch: the threshold for the batch's remaining individuals once
  // `exact_sorted` is known, the ranked values (ascending) of this batch's individuals evaluated
  // exactly so far, all of lower index than the ones still to come. An individual whose
  // fitness is >= the returned value has no influence on the run. Default: just above the
  // exact_ranks_needed()-th of them (ties evaluated in full), or selection_threshold() if lower;
  // +inf while neither applies.
  virtual double race_threshold(const std::vector<double>& exact_sorted) const;
  // Racing: after the first exact_ranks_needed() individuals, the batch is evaluated in chunks of
  // this many, each against the race_threshold of the values known before it. Default: the
  // evaluator's width (`workers`), the most parallel; a strategy that reports a statistic a
  // stopped individual can enter (a batch median beyond its exact ranks) returns a size that
  // does not depend on `workers`, so that the statistic is the same for any number of threads.
  virtual std::size_t race_chunk(std::size_t workers) const { return workers; }

  // Complete state as JSON: population (with step sizes and ages) or distribution, seed and
  // generation (which key every random stream), best so far, evaluation counts, stop state.
  // Doubles round-trip exactly (non-finite values are written as strings).
  virtual nlohmann::json save_state() const = 0;
  // Restores a state saved by a strategy of the same name, dimension and options; afterwards
  // the run continues bit-identically. Throws CheckpointError on a mismatch or malformed state.
  virtual void load_state(const nlohmann::json& state) = 0;
  // False for strategies whose state cannot be saved (NLopt keeps its state inside the library).
  virtual bool can_resume() const { return true; }

  std::size_t dimension() const { return bounds_.dimension(); }
  const Bounds& bounds() const { return bounds_; }
  // Best point told so far (empty before the first tell) and its fitness (+inf before).
  const std::vector<double>& best_x() const { return best_x_; }
  double best_fitness() const { return best_fitness_; }
  // Completed generations (tell() calls) and evaluated individuals, over all restarts.
  std::uint64_t generation() const { return generation_; }
  std::uint64_t evaluations() const { return evaluations_; }
  StopReason stop_reason() const { return stop_reason_; }
  // Human-readable detail of the stop reason (empty while running).
  const std::string& stop_detail() const { return stop_detail_; }
  bool should_stop() const { return stop_reason_ != StopReason::kNone; }

  // A point evaluated outside the search (the model a refit extends, say): counted as one
  // evaluation and kept as the best so far if it is, so the run never ends worse than it. It
  // does not enter the search's own state (population, mean, covariance). Throws
  // std::invalid_argument if x has the wrong size or lies outside the bounds.
  void record_incumbent(const std::vector<double>& x, double fitness);

 protected:
  // Throws std::invalid_argument if the bounds are invalid.
  explicit Strategy(Bounds bounds);

  // Counts one evaluation and updates the best so far (strictly better only, so among equal
  // fitness the one recorded first wins). Call in batch index order.
  void record_evaluation(const std::vector<double>& x, double fitness);
  void stop(StopReason reason, std::string detail);
  // The fields of this base class, for the derived save_state/load_state.
  nlohmann::json save_common() const;
  // The start of every derived save_state: name, dimension, the options that must match on
  // load, the common fields, and the random state. Every draw comes from a stream keyed by
  // (seed, generation, individual, purpose) and starts at counter 0, so seed and generation
  // are the whole random state.
  nlohmann::json save_header(nlohmann::json options, std::uint64_t seed) const;
  void load_common(const nlohmann::json& common);
  // Throws CheckpointError unless state["strategy"] == name() and state["dimension"] matches.
  void check_identity(const nlohmann::json& state) const;

  Bounds bounds_;
  std::uint64_t generation_ = 0;
  std::uint64_t evaluations_ = 0;
  std::vector<double> best_x_;
  double best_fitness_ = std::numeric_limits<double>::infinity();
  StopReason stop_reason_ = StopReason::kNone;
  std::string stop_detail_;
};

}  // namespace motoflex_es
