#include "motoflex/sim/parallel_rollouts.hpp"

#include <omp.h>

#include "motoflex/sim/ode_runtime.hpp"

namespace motoflex {

std::vector<RolloutResult> run_rollouts(const std::vector<RolloutJob>& jobs, int threads) {
  std::vector<RolloutResult> results(jobs.size());
  ensure_ode_ready();  // process-wide init happens once, before any worker starts
  const int count = static_cast<int>(jobs.size());
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads > 0 ? threads : 1)
  for (int i = 0; i < count; ++i) {
    const RolloutJob& job = jobs[i];
    results[i] = run_rollout(*job.model, *job.parameters, *job.commands, job.options);
  }
  return results;
}

}  // namespace motoflex
