#include "fit_on_ranks.hpp"

#include <csignal>
#include <cstdio>
#include <exception>
#include <optional>
#include <stdexcept>
#include <string>

#include "fit_console.hpp"
#include "motoflex/fit/fit_problem.hpp"
#include "motoflex_es/mpi_evaluator.hpp"
#include "motoflex_es/mpi_world.hpp"
#include "report_after_run.hpp"

namespace motoflex::cli {
namespace {

std::string rank_list(const std::vector<int>& ranks) {
  std::string text;
  for (int r : ranks) text += (text.empty() ? "" : ", ") + std::to_string(r);
  return text;
}

// Every rank loads the config; rank 0 first, so that it reports bad input once and files it
// derives (imported logs) exist before the others look. Returns nullopt on a worker when rank 0
// failed (rank 0 reports why).
std::optional<FitConfig> load_on_every_rank(const motoflex_es::MpiWorld& world,
                                            const std::function<FitConfig()>& load_config) {
  std::optional<FitConfig> config;
  std::exception_ptr error;
  if (world.rank() == 0) {
    try {
      config.emplace(load_config());
    } catch (...) {
      error = std::current_exception();
    }
  }
  const std::string root_hash = world.broadcast_from_root(config ? config->hash : std::string());
  if (root_hash.empty()) {
    if (error) std::rethrow_exception(error);
    return std::nullopt;
  }
  if (world.rank() != 0) {
    try {
      config.emplace(load_config());
    } catch (...) {
      error = std::current_exception();
    }
  }
  const bool same = config && config->hash == root_hash;
  const std::vector<int> failed = world.failed_ranks(same);
  if (failed.empty()) return config;
  if (world.rank() == 0) {
    throw std::runtime_error("MPI rank(s) " + rank_list(failed) +
                             " could not load the fit config of rank 0 (see their messages)");
  }
  if (error) std::rethrow_exception(error);
  if (!same) {
    throw std::runtime_error("MPI rank " + std::to_string(world.rank()) +
                             ": the fit config, its scenario or its logs differ from rank 0's "
                             "(config hash " +
                             config->hash + " vs " + root_hash + ")");
  }
  return std::nullopt;  // this rank is fine; another worker reports
}

}  // namespace

int run_fit_on_ranks(const std::function<FitConfig()>& load_config, bool resume) {
  const int launched = motoflex_es::launcher_process_count();
  if (launched <= 1) {
    FitConfig config = load_config();
    const std::string out_dir = config.out_dir;
    const int code = run_fit_on_console(std::move(config), resume);
    write_report_after_run(out_dir);
    return code;
  }
  if (!motoflex_es::mpi_built_in()) {
    throw std::runtime_error("started as one of " + std::to_string(launched) +
                             " MPI processes, but this build has no MPI support (reconfigure "
                             "with -DMOTOFLEX_WITH_MPI=ON and libopenmpi-dev installed)");
  }
  const motoflex_es::MpiWorld world;
  if (world.size() != launched) {
    throw std::runtime_error("the launcher started " + std::to_string(launched) +
                             " processes but MPI sees " + std::to_string(world.size()) +
                             " (with srun, pass --mpi=pmix or use mpirun)");
  }
  const std::optional<FitConfig> config = load_on_every_rank(world, load_config);
  if (!config) return 2;

  if (world.rank() != 0) {
    // Rank 0 decides when to stop (after the current generation, with a checkpoint) and then
    // releases the workers; a worker that died on SIGINT/SIGTERM would take the job down first.
    std::signal(SIGINT, SIG_IGN);
    std::signal(SIGTERM, SIG_IGN);
    FitProblem problem(*config);
    motoflex_es::serve_mpi_evaluations(world, problem, config->threads);
    return 0;
  }
  int code = 0;
  {
    // The evaluator's destructor releases the workers, also when the fit throws.
    motoflex_es::MpiEvaluator evaluator(world, config->threads);
    std::printf("evaluating on %s\n", evaluator.name().c_str());
    code = run_fit_on_console(*config, resume, &evaluator);
  }
  write_report_after_run(config->out_dir);  // rank 0 alone writes the run dir
  return code;
}

}  // namespace motoflex::cli
