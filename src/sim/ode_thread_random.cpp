// ODE's random generator, one per thread, and the quick step that seeds it per rollout.
//
// dWorldQuickStep reorders its constraint rows with dRandInt, which draws from dRand, ODE's
// linear congruential generator on one process-global 32-bit state. libode calls dRand through
// its procedure linkage table, so the definition below, linked into the program, replaces the
// library's for every caller in the process (ELF symbol interposition): the same generator
// (state' = 1664525 · state + 1013904223 mod 2^32, the drawn number is the new state), but on a
// state each thread owns. seeded_quick_step() loads a rollout's state into it around each quick
// step (a world's step runs on the calling thread: each world has a self-threaded
// implementation, rollout.cpp), so parallel quick rollouts neither share nor lock anything. Whether
// the replacement is in effect is probed once (a program that loads libode in a way that binds it
// to its own dRand keeps a process-wide lock around libode's generator instead).

#include <ode/ode.h>

#include <cstdint>
#include <mutex>

#include "ode_quick_step.hpp"

namespace motoflex::detail {
namespace {

thread_local std::uint32_t thread_random_state = 0;

bool probe_thread_random() {
  const unsigned long library_state_before = dRandGetSeed();
  const std::uint32_t saved = thread_random_state;
  thread_random_state = 12345u;
  // dRandInt is the library's; the dRand it calls is ours only if the interposition works.
  static_cast<void>(dRandInt(1000));
  const bool ours = thread_random_state == 1664525u * 12345u + 1013904223u &&
                    dRandGetSeed() == library_state_before;
  thread_random_state = saved;
  return ours;
}

}  // namespace

std::uint32_t& ode_thread_random_state() {
  return thread_random_state;
}

bool ode_random_is_per_thread() {
  static const bool per_thread = probe_thread_random();
  return per_thread;
}

int seeded_quick_step(dWorldID world, double dt_s, unsigned long& seed) {
  if (ode_random_is_per_thread()) {
    thread_random_state = static_cast<std::uint32_t>(seed);
    const int ok = dWorldQuickStep(world, dt_s);
    seed = thread_random_state;
    return ok;
  }
  // The lock guards ODE's global random state, the one piece of process-wide mutable state the
  // step touches; quick steps of parallel rollouts then take turns.
  static std::mutex quick_step_mutex;
  const std::lock_guard<std::mutex> lock(quick_step_mutex);
  dRandSetSeed(seed);
  const int ok = dWorldQuickStep(world, dt_s);
  seed = dRandGetSeed();
  return ok;
}

}  // namespace motoflex::detail

// Replaces libode's dRand (declared in <ode/misc.h>); see the comment at the top.
unsigned long dRand(void) {
  std::uint32_t& state = motoflex::detail::thread_random_state;
  state = 1664525u * state + 1013904223u;
  return state;
}
