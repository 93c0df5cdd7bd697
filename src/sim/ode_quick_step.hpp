#pragma once

// Internal to the rollout: dWorldQuickStep made reproducible whatever the threads.

#include <ode/ode.h>

namespace motoflex::detail {

// One dWorldQuickStep of `world` with the caller's own random seed. ODE reorders the
// constraint rows with its process-global dRandInt, so the step runs under a process-wide lock
// with `seed` swapped in, and the seed ODE leaves is stored back into it: a rollout's result
// then depends only on its own history (its seed starting at 0 is a fresh process's), not on
// which other rollouts stepped in between. Returns dWorldQuickStep's result.
int seeded_quick_step(dWorldID world, double dt_s, unsigned long& seed);

}  // namespace motoflex::detail
