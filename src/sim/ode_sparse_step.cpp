// dWorldStep with motoflex's LCP solver.
//
// dWorldStep forms its constraint problem and hands it to dxSolveLCP, a libode function that
// libode calls through its procedure linkage table. The definition below, linked into the
// program, replaces it for every caller in the process (ELF symbol interposition, as
// ode_thread_random.cpp does for dRand). It solves with the calling thread's active
// SparseStepState, which sparse_step() sets around its dWorldStep; with none active (the `step`
// solver, or any other ODE user) it calls libode's own solver, so `step` stays bit-identical.
//
// The interface is libode 0.16's (Debian 12): dxSolveLCP(arena, n, A, pairsbx, w, nub,
// pairslh, findex) with A's lower triangle row-major at stride dPAD(n) = n rounded up to a
// multiple of 4 (n itself when n ≤ 1), b and x interleaved in pairsbx (b at 2i, x at 2i + 1),
// lo and hi interleaved in pairslh, w optional. tests/sim/sparse_step_test.cpp checks these
// against libode's own solver on the Nao's problems.

#include "ode_sparse_step.hpp"

#include <dlfcn.h>

#include "motoflex/sim/ode_runtime.hpp"

struct dxWorldProcessMemArena;

namespace motoflex::detail {
namespace {

using OdeSolveLcp = void (*)(dxWorldProcessMemArena*, unsigned, double*, double*, double*, unsigned,
                             double*, int*);

// libode's dxSolveLCP (the next definition after ours in the lookup order).
OdeSolveLcp libode_solve_lcp() {
  static const auto solve = reinterpret_cast<OdeSolveLcp>(
      dlsym(RTLD_NEXT, "_Z10dxSolveLCPP22dxWorldProcessMemArenajPdS1_S1_jS1_Pi"));
  return solve;
}

thread_local SparseStepState* active_state = nullptr;
thread_local long replaced_calls = 0;

bool probe_replacement() {
  // A body on a hinge to the world: dWorldStep calls dxSolveLCP once.
  ensure_ode_ready();
  dWorldID world = dWorldCreate();
  dBodyID body = dBodyCreate(world);
  dJointID hinge = dJointCreateHinge(world, nullptr);
  dJointAttach(hinge, body, nullptr);
  dJointSetHingeAxis(hinge, 0.0, 0.0, 1.0);
  dJointSetHingeParam(hinge, dParamFMax, 1.0);  // a bounded motor row, so the LCP is general
  const long before = replaced_calls;
  dWorldStep(world, 1e-3);
  const bool replaced = replaced_calls > before;
  dWorldDestroy(world);
  return replaced;
}

}  // namespace

bool ode_lcp_is_replaced() {
  static const bool replaced = probe_replacement();
  return replaced;
}

int sparse_step(dWorldID world, double dt_s, SparseStepState& state) {
  // Cleared also when an ODE error is thrown out of the step (motoflex's handler throws).
  struct Activation {
    explicit Activation(SparseStepState& s) { active_state = &s; }
    ~Activation() { active_state = nullptr; }
    Activation(const Activation&) = delete;
    Activation& operator=(const Activation&) = delete;
  } activation(state);
  return dWorldStep(world, dt_s);
}

}  // namespace motoflex::detail

// Replaces libode's dxSolveLCP; see the comment at the top.
void dxSolveLCP(dxWorldProcessMemArena* arena, unsigned n, double* a, double* pairs_bx, double* w,
                unsigned nub, double* pairs_lh, int* findex) {
  using namespace motoflex::detail;
  ++replaced_calls;
  SparseStepState* state = active_state;
  if (state == nullptr || n == 0) {
    libode_solve_lcp()(arena, n, a, pairs_bx, w, nub, pairs_lh, findex);
    return;
  }
  // ODE's arrays as they are: b and x interleaved in pairs_bx, lo and hi in pairs_lh. The
  // solver writes x and the friction bounds back only once it has solved the problem, so a
  // problem it hands back reaches libode's solver untouched.
  BoxLcpView problem;
  problem.n = n;
  problem.a_lower = a;
  problem.stride = n > 1 ? (n + 3u) & ~3u : n;
  problem.b = pairs_bx;
  problem.lo = pairs_lh;
  problem.hi = pairs_lh + 1;
  problem.vector_stride = 2;
  problem.findex = findex;
  if (!state->solver.solve(problem, pairs_bx + 1, pairs_lh, pairs_lh + 1, w)) {
    ++state->fallbacks;
    libode_solve_lcp()(arena, n, a, pairs_bx, w, nub, pairs_lh, findex);
  }
}
