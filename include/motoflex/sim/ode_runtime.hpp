#pragma once

namespace motoflex {

// ODE's process-wide set-up. `ensure_ode_ready()` must be called by every thread before it
// touches ODE: the first call in the process runs dInitODE2 (exactly once, whatever the
// threads) and installs error handlers that turn ODE errors into ModelError exceptions; each
// thread's first call allocates ODE's per-thread data (ode_and_titan8.md §2.6). Cheap after
// the first call on a thread.
void ensure_ode_ready();

}  // namespace motoflex
