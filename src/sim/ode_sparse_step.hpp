#pragma once

// Internal to the rollout: dWorldStep with its LCP solved by motoflex's sparse block-pivoting
// solver (box_lcp.hpp) instead of libode's dense Dantzig solver: the same exact LCP, the same
// answer up to rounding, fewer operations on a robot.

#include <ode/ode.h>

#include "box_lcp.hpp"

namespace motoflex::detail {

// One rollout's LCP solver state; owned by the rollout, used by one thread at a time.
struct SparseStepState {
  BoxLcpSolver solver;
  long fallbacks = 0;  // problems handed back to libode's solver (pivoting did not settle)
};

// One dWorldStep of `world` whose LCPs go to `state`'s solver (a problem it cannot settle goes
// to libode's). Returns dWorldStep's result.
int sparse_step(dWorldID world, double dt_s, SparseStepState& state);

// True when libode calls motoflex's LCP entry point (probed once per process): motoflex defines
// libode's internal dxSolveLCP, and ELF symbol interposition routes libode's calls to it when
// the definition is in the program (not when motoflex is loaded as a local module).
bool ode_lcp_is_replaced();

}  // namespace motoflex::detail
