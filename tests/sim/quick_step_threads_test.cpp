// motoflex's dRand (src/sim/ode_thread_random.cpp) gives every thread its own copy of ODE's
// generator, so quick rollouts run side by side without a lock (determinism_test.cpp: parallel
// quick rollouts give the bits they give alone).

#include <gtest/gtest.h>
#include <ode/ode.h>

#include <cstdint>
#include <thread>

#include "ode_quick_step.hpp"

namespace motoflex {
namespace {

TEST(QuickStepThreadsTest, LibodeDrawsFromTheThreadsOwnCopyOfItsGenerator) {
  ASSERT_TRUE(detail::ode_random_is_per_thread())
      << "libode binds dRand to its own definition here: quick steps fall back to the lock";

  // ODE's own self-check of its sequence from state 0 (it resets the library's global state,
  // which no longer feeds anything, and draws through dRand): ours is the same generator.
  detail::ode_thread_random_state() = 0;
  EXPECT_EQ(dTestRand(), 1);

  // The draws of another thread leave this thread's state where it is.
  detail::ode_thread_random_state() = 7;
  const unsigned long library_state = dRandGetSeed();
  std::uint32_t other_thread_state = 0;
  std::thread other([&other_thread_state] {
    detail::ode_thread_random_state() = 100;
    for (int i = 0; i < 1000; ++i) static_cast<void>(dRandInt(50));
    other_thread_state = detail::ode_thread_random_state();
  });
  other.join();
  EXPECT_EQ(detail::ode_thread_random_state(), 7u);
  EXPECT_NE(other_thread_state, 100u);
  EXPECT_EQ(dRandGetSeed(), library_state);
}

}  // namespace
}  // namespace motoflex
