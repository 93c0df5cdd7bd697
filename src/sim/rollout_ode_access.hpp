#pragma once

// Internal to the sim module and its tests: the ODE handles behind a Rollout, for checks that
// must look at the engine itself (joint conventions, flex springs, contact forces). Everything
// outside `sim` uses the ODE-free accessors of rollout.hpp.

#include <ode/ode.h>

#include <cstddef>

#include "motoflex/sim/rollout.hpp"
#include "ode_sparse_step.hpp"

namespace motoflex {

struct RolloutOdeAccess {
  static dWorldID world(const Rollout& rollout);
  static dBodyID body(const Rollout& rollout, std::size_t index);  // nullptr: a static body
  static dJointID joint(const Rollout& rollout, std::size_t index);
  // The rollout's LCP solver state (solver `sparse`): its counts of solved and handed-back
  // problems.
  static const detail::SparseStepState& sparse_lcp(const Rollout& rollout);
};

}  // namespace motoflex
