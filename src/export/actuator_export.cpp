#include "motoflex/export/actuator_export.hpp"

#include <cmath>

#include "motoflex/core/error.hpp"
#include "motoflex/sim/resolved_parameters.hpp"

namespace motoflex {
namespace {

// Velocity gain of a stiff position actuator standing in for a velocity constraint, as a
// multiple of the joint's inertia per time step (see actuator_export.hpp).
constexpr double kStiffServoInertiaSteps = 5.0;

bool in_subtree(const RobotModel& model, int body, int joint) {
  while (body >= 0) {
    const int parent_joint = model.bodies[body].parent_joint;
    if (parent_joint < 0) return false;
    if (parent_joint == joint) return true;
    body = model.joints[parent_joint].parent_body;
  }
  return false;
}

double no_load_speed(double effort_nm, double damping_nm_s_per_rad) {
  return damping_nm_s_per_rad > 0.0 ? effort_nm / damping_nm_s_per_rad : 0.0;
}

}  // namespace

double subtree_inertia_kg_m2(const RobotModel& model, std::size_t actuator) {
  const ActuatorSpec& spec = model.actuators.at(actuator);
  const JointSpec& joint = model.joints[spec.joint];
  const Eigen::Vector3d axis = spec.axis == 1 ? joint.axis1_W0 : joint.axis2_W0;
  double inertia = 0.0;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (!in_subtree(model, static_cast<int>(b), spec.joint)) continue;
    const BodySpec& body = model.bodies[b];
    Eigen::Vector3d r = body.com_W0_m - joint.anchor_W0_m;
    r -= axis * axis.dot(r);
    inertia += body.mass_kg * r.squaredNorm() + axis.dot(body.inertia_kg_m2 * axis);
  }
  return inertia;
}

std::vector<ActuatorExport> export_actuators(const ExportInput& input) {
  const RobotModel& model = input.model;
  // The simulator's own reading of the parameters, so the export sees exactly the numbers a
  // rollout uses (for the motoflex servo B·σ² is already reflected through the gear).
  const detail::ResolvedParameters resolved =
      detail::resolve_parameters(model, input.parameters, input.servo);
  std::vector<ActuatorExport> out(model.actuators.size());
  for (std::size_t i = 0; i < model.actuators.size(); ++i) {
    const ActuatorSpec& spec = model.actuators[i];
    const detail::ActuatorParameters& p = resolved.actuators[i];
    ActuatorExport& a = out[i];
    a.joint = spec.name;
    a.group = spec.group;
    // A robot without joint stops (robot.yaml joint_stops: false) exports none either.
    a.limited = model.joint_stops && std::isfinite(spec.lower_rad) && std::isfinite(spec.upper_rad);
    a.lower_rad = a.limited ? spec.lower_rad : 0.0;
    a.upper_rad = a.limited ? spec.upper_rad : 0.0;
    switch (input.servo) {
      case ServoKind::kMotoflex: {
        if (!(p.motor.resistance_ohm > 0.0)) throw ModelError("motor.R_ohm must be positive");
        const double volts_to_torque = p.gear.ratio * p.motor.stiffness *
                                       p.motor.torque_constant_nm_per_a / p.motor.resistance_ohm;
        a.kp_nm_per_rad = volts_to_torque * p.pid.kp_v_per_rad;
        a.kv_nm_s_per_rad = volts_to_torque * p.pid.kd_v_s_per_rad;
        a.effort_nm = volts_to_torque * p.motor.supply_v;
        a.damping_nm_s_per_rad = p.friction.viscous_nm_s_per_rad + p.back_emf_damping_nm_s_per_rad;
        a.friction_nm = p.friction.coulomb_nm;
        a.reduction = p.gear.ratio;
        a.armature_kg_m2 = p.gear.mass_kg_m2;
        break;
      }
      case ServoKind::kBench: {
        const BenchServoParams& b = p.bench;
        if (!(b.resistance_ohm > 0.0)) throw ModelError("bench.R_ohm must be positive");
        const double volts_to_torque = b.torque_constant_nm_per_a / b.resistance_ohm;
        a.kp_nm_per_rad = volts_to_torque * b.supply_v * b.error_gain * b.kp;
        a.effort_nm = volts_to_torque * b.supply_v * b.max_duty;
        a.damping_nm_s_per_rad =
            p.friction.viscous_nm_s_per_rad + b.torque_constant_nm_per_a * volts_to_torque;
        a.friction_nm = p.friction.coulomb_nm;
        a.armature_kg_m2 = resolved.bench_load.armature_kg_m2;
        break;
      }
      case ServoKind::kIdeal:
      case ServoKind::kVelocity: {
        const double inertia = subtree_inertia_kg_m2(model, i);
        a.kv_nm_s_per_rad = kStiffServoInertiaSteps * inertia / input.dt_s;
        if (input.servo == ServoKind::kIdeal) {
          a.kp_nm_per_rad = a.kv_nm_s_per_rad / input.dt_s;
          a.effort_nm = resolved.ideal.torque_max_nm;
          a.command_is_next_angle = true;
        } else {
          a.kp_nm_per_rad = a.kv_nm_s_per_rad * p.velocity.gain_per_s;
          a.effort_nm = p.velocity.torque_max_nm;
        }
        break;
      }
    }
    a.velocity_rad_s = no_load_speed(a.effort_nm, a.damping_nm_s_per_rad);
  }
  return out;
}

FlexExport export_flex(const ExportInput& input) {
  bool has_flex = false;
  for (const auto& j : input.model.joints) has_flex = has_flex || j.kind == JointKind::kFlex;
  if (!has_flex) return {};
  const ParameterSet& p = input.parameters;
  return {p.get("flex.spring_nm_per_rad"), p.get("flex.damping_nm_s_per_rad"),
          p.get("flex.friction_nm")};
}

}  // namespace motoflex
