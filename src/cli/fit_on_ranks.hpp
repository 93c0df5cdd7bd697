#pragma once

#include <functional>

#include "motoflex/fit/fit_config.hpp"

namespace motoflex::cli {

// Runs `motoflex fit` / `motoflex resume` in this process, or distributed when an MPI launcher
// (mpirun, srun) started this process as one of several (motoflex_es::launcher_process_count()
// > 1): then every rank loads the config with `load_config` (rank 0 first; the others must get
// the same config hash), rank 0 runs the fit with an MpiEvaluator and writes every file and
// progress line, and the other ranks evaluate their slices of each batch until rank 0 releases
// them — also when rank 0 fails, so that no rank hangs. Returns the process exit code; rank 0
// rethrows its errors (bad input: InputError), a worker whose config differs from rank 0's
// throws. Threads per rank: config.threads.
int run_fit_on_ranks(const std::function<FitConfig()>& load_config, bool resume);

}  // namespace motoflex::cli
