#pragma once

#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {

// One rollout job: every referenced object must outlive the call.
struct RolloutJob {
  const RobotModel* model = nullptr;
  const ParameterSet* parameters = nullptr;
  const CommandTrajectory* commands = nullptr;
  RolloutOptions options;
};

// Runs the jobs on `threads` OpenMP threads (1 = serially in the calling thread). Results are
// stored by job index, and each rollout owns its ODE world, so with dWorldStep the results are
// bit-identical for any thread count.
std::vector<RolloutResult> run_rollouts(const std::vector<RolloutJob>& jobs, int threads);

}  // namespace motoflex
