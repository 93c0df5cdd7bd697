#include "motoflex_es/mpi_evaluator.hpp"

#include <mpi.h>

#include <cstdint>
#include <exception>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "mpi_wait.hpp"

namespace motoflex_es {
namespace {

enum class Command : std::uint64_t { kStop = 0, kEvaluate = 1 };

// What rank 0 broadcasts before every batch. Sent as bytes: the ranks of one job run the same
// binary (homogeneous cluster).
struct BatchHeader {
  Command command = Command::kStop;
  std::uint64_t batch_size = 0;
  std::uint64_t dimension = 0;
  std::uint64_t generation = 0;
  std::uint64_t first_individual = 0;
  std::uint64_t counters = 0;  // length of Problem::counters() on rank 0
  double stop_threshold = std::numeric_limits<double>::infinity();
};

// Rank 0's view of one batch: the fitness by index and who failed.
struct BatchOutcome {
  std::vector<double> fitness;
  std::exception_ptr own_error;  // rank 0's own slice threw
  int failed_rank = -1;          // lowest worker whose slice threw
  std::string failed_message;
};

int to_int(std::size_t value) {
  if (value > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::length_error("MpiEvaluator: a batch too large for one MPI message");
  }
  return static_cast<int>(value);
}

std::unique_ptr<Evaluator> make_local_evaluator(int threads) {
  if (threads == 1) return std::make_unique<SerialEvaluator>();
  return std::make_unique<OpenMpEvaluator>(threads);
}

// This rank's candidates of the batch that rank 0 holds in `flat_xs` (row-major).
std::vector<std::vector<double>> scatter_candidates(const std::vector<double>& flat_xs,
                                                    const std::vector<int>& x_counts,
                                                    const std::vector<int>& x_offsets,
                                                    std::size_t my_count, std::size_t dimension) {
  std::vector<double> my_flat(my_count * dimension);
  MPI_Request request;
  MPI_Iscatterv(flat_xs.data(), x_counts.data(), x_offsets.data(), MPI_DOUBLE, my_flat.data(),
                to_int(my_flat.size()), MPI_DOUBLE, 0, MPI_COMM_WORLD, &request);
  wait_without_spinning(request);
  std::vector<std::vector<double>> my_xs(my_count);
  for (std::size_t k = 0; k < my_count; ++k) {
    my_xs[k].assign(my_flat.begin() + static_cast<std::ptrdiff_t>(k * dimension),
                    my_flat.begin() + static_cast<std::ptrdiff_t>((k + 1) * dimension));
  }
  return my_xs;
}

// Every rank's error message on rank 0, collectively: per rank the message plus a newline, or
// empty when that rank had no error (elsewhere an empty list).
std::vector<std::string> gather_error_messages(bool root, int ranks,
                                               const std::optional<std::string>& my_error) {
  const int my_error_length = my_error ? to_int(my_error->size()) + 1 : 0;  // 0: no error
  std::vector<int> error_lengths(root ? static_cast<std::size_t>(ranks) : 0);
  MPI_Request request;
  MPI_Igather(&my_error_length, 1, MPI_INT, error_lengths.data(), 1, MPI_INT, 0, MPI_COMM_WORLD,
              &request);
  wait_without_spinning(request);
  std::vector<int> error_offsets(error_lengths.size(), 0);
  int all_error_length = 0;
  for (std::size_t i = 0; i < error_lengths.size(); ++i) {
    error_offsets[i] = all_error_length;
    all_error_length += error_lengths[i];
  }
  const std::string my_error_text = my_error ? *my_error + '\n' : std::string();
  std::string all_error_text(static_cast<std::size_t>(all_error_length), '\0');
  MPI_Igatherv(my_error_text.data(), my_error_length, MPI_CHAR, all_error_text.data(),
               error_lengths.data(), error_offsets.data(), MPI_CHAR, 0, MPI_COMM_WORLD, &request);
  wait_without_spinning(request);
  std::vector<std::string> errors(error_lengths.size());
  for (std::size_t i = 0; i < errors.size(); ++i) {
    errors[i] = all_error_text.substr(static_cast<std::size_t>(error_offsets[i]),
                                      static_cast<std::size_t>(error_lengths[i]));
  }
  return errors;
}

// Every rank's part of one batch, collectively; `flat_xs` (batch_size × dimension, row-major)
// matters on rank 0 only. Returns the gathered outcome on rank 0 (empty elsewhere).
BatchOutcome exchange_batch(const MpiWorld& world, Problem& problem, Evaluator& local,
                            const BatchHeader& header, const std::vector<double>& flat_xs) {
  const int ranks = world.size();
  const std::size_t dimension = header.dimension;
  std::vector<int> counts(static_cast<std::size_t>(ranks)), offsets(counts.size());
  std::vector<int> x_counts(counts.size()), x_offsets(counts.size());
  for (int r = 0; r < ranks; ++r) {
    const BatchSlice slice = batch_slice(header.batch_size, r, ranks);
    const auto i = static_cast<std::size_t>(r);
    counts[i] = to_int(slice.count);
    offsets[i] = to_int(slice.first);
    x_counts[i] = to_int(slice.count * dimension);
    x_offsets[i] = to_int(slice.first * dimension);
  }
  const BatchSlice mine = batch_slice(header.batch_size, world.rank(), ranks);

  const std::vector<std::vector<double>> my_xs =
      scatter_candidates(flat_xs, x_counts, x_offsets, mine.count, dimension);

  EvaluationContext context;
  context.generation = header.generation;
  context.first_individual = header.first_individual + mine.first;
  context.stop_threshold = header.stop_threshold;
  std::vector<std::uint64_t> before = problem.counters();
  before.resize(header.counters, 0);
  std::vector<double> my_fitness(mine.count, std::numeric_limits<double>::quiet_NaN());
  std::exception_ptr error;
  std::string message;
  if (mine.count > 0) {
    try {
      local.evaluate(problem, my_xs, my_fitness, context);
    } catch (const std::exception& e) {
      error = std::current_exception();
      message = e.what();
    } catch (...) {
      error = std::current_exception();
      message = "unknown exception";
    }
  }
  // Rank 0 already counted its own slice in its replica; workers send what theirs added.
  std::vector<std::uint64_t> increments(header.counters, 0);
  if (world.rank() != 0) {
    std::vector<std::uint64_t> after = problem.counters();
    after.resize(header.counters, 0);
    for (std::size_t i = 0; i < increments.size(); ++i) increments[i] = after[i] - before[i];
  }

  BatchOutcome outcome;
  const bool root = world.rank() == 0;
  if (root) outcome.fitness.assign(header.batch_size, std::numeric_limits<double>::quiet_NaN());
  MPI_Request request;
  MPI_Igatherv(my_fitness.data(), to_int(my_fitness.size()), MPI_DOUBLE, outcome.fitness.data(),
               counts.data(), offsets.data(), MPI_DOUBLE, 0, MPI_COMM_WORLD, &request);
  wait_without_spinning(request);

  const std::vector<std::string> errors = gather_error_messages(
      root, ranks, error ? std::optional<std::string>(message) : std::nullopt);

  std::vector<std::uint64_t> summed(header.counters, 0);
  if (header.counters > 0) {
    MPI_Ireduce(increments.data(), summed.data(), to_int(increments.size()), MPI_UINT64_T, MPI_SUM,
                0, MPI_COMM_WORLD, &request);
    wait_without_spinning(request);
  }

  if (root) {
    problem.add_counters(summed);
    outcome.own_error = error;
    for (int r = 1; r < ranks && outcome.failed_rank < 0; ++r) {
      const auto i = static_cast<std::size_t>(r);
      if (errors[i].empty()) continue;
      outcome.failed_rank = r;
      outcome.failed_message = errors[i].substr(0, errors[i].size() - 1);
    }
  }
  return outcome;
}

void broadcast_header(BatchHeader& header) {
  MPI_Request request;
  MPI_Ibcast(&header, static_cast<int>(sizeof header), MPI_BYTE, 0, MPI_COMM_WORLD, &request);
  wait_without_spinning(request);
}

}  // namespace

MpiEvaluator::MpiEvaluator(const MpiWorld& world, int threads_per_rank)
    : world_(world), threads_per_rank_(threads_per_rank) {
  if (world.rank() != 0) {
    throw std::logic_error("MpiEvaluator: only rank 0 evaluates through the evaluator; rank " +
                           std::to_string(world.rank()) + " must call serve_mpi_evaluations");
  }
  local_ = make_local_evaluator(threads_per_rank);
  threads_per_rank_ = local_->workers();
}

MpiEvaluator::~MpiEvaluator() {
  stop_workers();
}

std::string MpiEvaluator::name() const {
  return "mpi(" + std::to_string(world_.size()) + (world_.size() == 1 ? " rank x " : " ranks x ") +
         std::to_string(threads_per_rank_) + (threads_per_rank_ == 1 ? " thread)" : " threads)");
}

int MpiEvaluator::workers() const {
  return world_.size() * threads_per_rank_;
}

void MpiEvaluator::stop_workers() {
  if (stopped_) return;
  stopped_ = true;
  BatchHeader header;
  header.command = Command::kStop;
  broadcast_header(header);
}

void MpiEvaluator::evaluate(Problem& problem, const std::vector<std::vector<double>>& xs,
                            std::vector<double>& fitness, const EvaluationContext& context) {
  if (stopped_) throw std::logic_error("MpiEvaluator: evaluate after stop_workers");
  fitness.assign(xs.size(), std::numeric_limits<double>::quiet_NaN());
  if (xs.empty()) return;
  BatchHeader header;
  header.command = Command::kEvaluate;
  header.batch_size = xs.size();
  header.dimension = problem.dimension();
  header.generation = context.generation;
  header.first_individual = context.first_individual;
  header.counters = problem.counters().size();
  header.stop_threshold = context.stop_threshold;
  std::vector<double> flat_xs;
  flat_xs.reserve(xs.size() * header.dimension);
  for (const auto& x : xs) {
    if (x.size() != header.dimension) {
      throw std::invalid_argument("MpiEvaluator: a point of dimension " + std::to_string(x.size()) +
                                  " for a problem of dimension " +
                                  std::to_string(header.dimension));
    }
    flat_xs.insert(flat_xs.end(), x.begin(), x.end());
  }
  broadcast_header(header);
  BatchOutcome outcome = exchange_batch(world_, problem, *local_, header, flat_xs);
  if (outcome.own_error) std::rethrow_exception(outcome.own_error);
  if (outcome.failed_rank > 0) {
    throw std::runtime_error("MPI rank " + std::to_string(outcome.failed_rank) + ": " +
                             outcome.failed_message);
  }
  fitness = std::move(outcome.fitness);
}

void serve_mpi_evaluations(const MpiWorld& world, Problem& problem, int threads_per_rank) {
  if (world.rank() == 0) {
    throw std::logic_error("serve_mpi_evaluations: rank 0 evaluates through MpiEvaluator");
  }
  const std::unique_ptr<Evaluator> local = make_local_evaluator(threads_per_rank);
  const std::vector<double> no_points;
  while (true) {
    BatchHeader header;
    broadcast_header(header);
    if (header.command != Command::kEvaluate) return;
    exchange_batch(world, problem, *local, header, no_points);
  }
}

}  // namespace motoflex_es
