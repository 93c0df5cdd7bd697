#include "motoflex/sim/ode_runtime.hpp"

#include <ode/ode.h>

#include <cstdarg>
#include <cstdio>
#include <mutex>
#include <string>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

std::string format_ode_message(int code, const char* format, va_list args) {
  char buffer[512];
  std::vsnprintf(buffer, sizeof buffer, format, args);
  return "ODE error " + std::to_string(code) + ": " + buffer;
}

// ODE is C++ inside, so an exception thrown from its handler unwinds back to the rollout,
// which reports the run as failed instead of aborting the process.
[[noreturn]] void throw_ode_error(int code, const char* format, va_list args) {
  throw ModelError(format_ode_message(code, format, args));
}

// ODE prints solver notices (e.g. "LCP internal error") through this; a rollout that goes
// bad is caught by the divergence checks, so the notices are not printed from worker threads.
void ignore_ode_message(int, const char*, va_list) {}

}  // namespace

void ensure_ode_ready() {
  static std::once_flag init_flag;
  std::call_once(init_flag, [] {
    dInitODE2(0);
    dSetErrorHandler(throw_ode_error);
    dSetDebugHandler(throw_ode_error);
    dSetMessageHandler(ignore_ode_message);
  });
  thread_local bool thread_ready = false;
  if (!thread_ready) {
    dAllocateODEDataForThread(dAllocateMaskAll);
    thread_ready = true;
  }
}

}  // namespace motoflex
