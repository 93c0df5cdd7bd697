#include "motoflex/export/actuator_export.hpp"

#include <cmath>

#include "motoflex/export/servo_export.hpp"
#include "motoflex/model/joint_units.hpp"

namespace motoflex {
namespace {

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
    if (spec.prismatic) {  // a slider moves the subtree's mass along its axis
      inertia += body.mass_kg;
      continue;
    }
    Eigen::Vector3d r = body.com_W0_m - joint.anchor_W0_m;
    r -= axis * axis.dot(r);
    inertia += body.mass_kg * r.squaredNorm() + axis.dot(body.inertia_kg_m2 * axis);
  }
  return inertia;
}

std::vector<ActuatorExport> export_actuators(const ExportInput& input) {
  const RobotModel& model = input.model;
  std::vector<ActuatorExport> out(model.actuators.size());
  for (std::size_t i = 0; i < model.actuators.size(); ++i) {
    const std::string& law = actuator_servo_name(model, input.servo, i);
    const ServoExportRule& rule = servo_export_rule(law);
    const ParameterReader get(input.parameters, law);
    const ActuatorSpec& spec = model.actuators[i];
    ActuatorExport& a = out[i];
    a.joint = spec.name;
    a.group = spec.group;
    a.prismatic = spec.prismatic;
    // A robot without joint stops (robot.yaml joint_stops: false) exports none either.
    a.limited = model.joint_stops && std::isfinite(spec.lower_rad) && std::isfinite(spec.upper_rad);
    a.lower_rad = a.limited ? spec.lower_rad : 0.0;
    a.upper_rad = a.limited ? spec.upper_rad : 0.0;
    rule.fill(input, i, get, a);
    // Every robot has it (the effect catalog); the rollout reads it the same way.
    a.mounting_offset_rad =
        input.parameters.get(joint_parameter(spec, "mounting_offset", joint_units(spec).position));
    a.command_is_next_angle = rule.command_is_next_angle;
    // A rule that knows its law's speed limit sets it (pd_torque's torque-speed curve).
    if (a.velocity_rad_s == 0.0)
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
