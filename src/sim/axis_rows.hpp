#pragma once

// Internal to the rollout: the extra constraint rows a servo law may ask for on its actuated
// axis (an angular motor between the joint's two bodies: the armature's inertia row, a separate
// friction row, the motoflex law's damper) and the gravity torque on what a joint moves (the
// external torque of BAM's load-dependent friction).

#include <ode/ode.h>

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "motoflex/model/robot_model.hpp"
#include "ode_axis.hpp"

namespace motoflex::detail {

// An angular motor about `actuator`'s axis between its joint's two bodies (`bodies`: the
// rollout's ODE body per model body, nullptr for a welded one). Its row acts on the relative
// rate (ω_carrier − ω_other)·axis, ± the joint rate; on a slider a linear motor on the relative
// velocity. Parameters are left to the caller (set_axis_motor_param).
dJointID create_axis_motor(dWorldID world, const RobotModel& model,
                           const std::vector<dBodyID>& bodies, std::size_t actuator);

// dJointSetAMotorParam or dJointSetLMotorParam, whichever `motor` is (a slider's is linear).
void set_axis_motor_param(dJointID motor, int parameter, dReal value);

// Sets a one-axis angular motor's target velocity to its bodies' relative rate now: with
// unbounded force and CFM = h/J its row is the inertia J (see Rollout::Impl::add_inertia_row).
void target_current_rate(dJointID motor);

// The model bodies joint `joint` moves: its child and everything below it.
std::vector<int> moved_bodies(const RobotModel& model, int joint);

// axis · Σ (p_b − anchor) × m_b·g over `load_bodies` (N·m, our sign: the axis vectors are the
// physical axes of hinge and universal joints alike, so a positive torque turns the child
// positively).
double gravity_torque_nm(const OdeAxis& axis, const std::vector<dBodyID>& load_bodies,
                         const Eigen::Vector3d& gravity_m_s2);

}  // namespace motoflex::detail
