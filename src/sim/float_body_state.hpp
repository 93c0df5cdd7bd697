#pragma once

// Internal to the rollout: the 2011 program's single-precision body state, emulated.

#include <ode/ode.h>

namespace motoflex::detail {

// Rounds `body`'s position, orientation quaternion and linear and angular velocity to the
// nearest single-precision values, as an ODE built with dReal = float stores them between steps
// (motoflex_2011.md §1: the original cannot be built with double precision, and how it falls
// depends on the precision). Only the stored state is rounded; the step's own arithmetic stays
// in double, so this emulates the rounding that accumulates from step to step, not all of it.
void round_body_state_to_float(dBodyID body);

}  // namespace motoflex::detail
