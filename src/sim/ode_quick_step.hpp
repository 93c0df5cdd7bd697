#pragma once

// Internal to the rollout: dWorldQuickStep made reproducible whatever the threads.

#include <ode/ode.h>

#include <cstdint>

namespace motoflex::detail {

// One dWorldQuickStep of `world` with the caller's own random seed. ODE reorders the
// constraint rows with dRandInt; `seed` is loaded into the generator before the step and the
// state the step leaves is stored back into it, so a rollout's result depends only on its own
// history (its seed starting at 0 is a fresh process's), not on which other rollouts stepped in
// between. With the per-thread generator (ode_thread_random.cpp) parallel steps run freely;
// otherwise they take turns under a process-wide lock around ODE's global generator. Returns
// dWorldQuickStep's result.
int seeded_quick_step(dWorldID world, double dt_s, unsigned long& seed);

// The calling thread's state of ODE's generator when motoflex's dRand replaces libode's.
std::uint32_t& ode_thread_random_state();

// True when libode draws from ode_thread_random_state() (probed once per process).
bool ode_random_is_per_thread();

}  // namespace motoflex::detail
