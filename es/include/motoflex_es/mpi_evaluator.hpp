#pragma once

#include <memory>
#include <string>
#include <vector>

#include "motoflex_es/evaluator.hpp"
#include "motoflex_es/mpi_world.hpp"
#include "motoflex_es/problem.hpp"

namespace motoflex_es {

// Distributed evaluation over the ranks of an MpiWorld. Rank 0 runs the strategy (ask/tell,
// checkpoints, output) and uses this evaluator; every other rank holds its own replica of the
// Problem and sits in serve_mpi_evaluations. Per batch, every rank — rank 0 too — evaluates the
// fixed contiguous slice batch_slice(n, rank, ranks) with `threads_per_rank` OpenMP threads (serial
// for 1), with first_individual = the slice's first index and the batch's generation and
// stop_threshold; fitness is gathered by index (MPI_Gatherv). No process is ever spawned. So a
// deterministic problem gives bit-identical results for any number of ranks and threads.
//
// Per batch, collectively: a broadcast header (command, batch size, dimension, generation,
// first individual, stop threshold, number of problem counters), a scatterv of the points, a
// gatherv of the fitness, a gather(v) of each rank's error (if its slice threw), and a reduce of
// the growth of each worker's Problem::counters(), which rank 0 adds to its replica with
// Problem::add_counters. A header with the stop command ends the workers' loop. Each is the
// non-blocking MPI-3 call (MPI_Ibcast, ...) completed by polling with a short sleep, because
// OpenMPI's blocking calls spin a core while waiting (see src/mpi/mpi_wait.hpp).
//
// Errors: a worker whose slice throws still takes part in every collective and reports the
// message; evaluate() on rank 0 then rethrows rank 0's own exception, else throws
// std::runtime_error("MPI rank r: <message>") for the lowest failing rank (lowest indices first,
// as the other evaluators). The workers keep serving until stopped. stop_workers() (also called
// by the destructor, so an exception unwinding past the evaluator still releases the workers)
// sends the stop command once.
class MpiEvaluator final : public Evaluator {
 public:
  // Collective with serve_mpi_evaluations on the workers. `world` must outlive the evaluator
  // and this must be rank 0 (std::logic_error otherwise). threads_per_rank <= 0: OpenMP's
  // default.
  MpiEvaluator(const MpiWorld& world, int threads_per_rank);
  ~MpiEvaluator() override;
  MpiEvaluator(const MpiEvaluator&) = delete;
  MpiEvaluator& operator=(const MpiEvaluator&) = delete;

  void evaluate(Problem& problem, const std::vector<std::vector<double>>& xs,
                std::vector<double>& fitness, const EvaluationContext& context) override;
  // "mpi(2 ranks x 1 thread)"
  std::string name() const override;
  int workers() const override;

  // Ends serve_mpi_evaluations on every worker; later evaluate() calls throw std::logic_error.
  void stop_workers();

 private:
  const MpiWorld& world_;
  int threads_per_rank_;
  std::unique_ptr<Evaluator> local_;
  bool stopped_ = false;
};

// The loop of a worker rank (rank > 0): receive a batch slice, evaluate it on `problem` (this
// rank's replica) with `threads_per_rank` threads, send the fitness back; returns when rank 0
// sends the stop command. Exceptions of the problem are reported to rank 0, not thrown here.
void serve_mpi_evaluations(const MpiWorld& world, Problem& problem, int threads_per_rank);

}  // namespace motoflex_es
