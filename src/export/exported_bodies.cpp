#include "exported_bodies.hpp"

#include <algorithm>
#include <cmath>

#include "motoflex/core/build_info.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/export/servo_export.hpp"
#include "motoflex/model/body_kinematics.hpp"

namespace motoflex::detail {

std::vector<ExportedBody> exported_bodies(const ExportInput& input, const Eigen::Vector3d& offset_m,
                                          bool armature_in_bench_arm) {
  const RobotModel& model = input.model;
  std::vector<ExportedBody> out(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const BodySpec& spec = model.bodies[b];
    ExportedBody& body = out[b];
    body.spec = &spec;
    body.mass_kg = spec.mass_kg;
    body.com_m = spec.com_W0_m;
    body.inertia_kg_m2 = spec.inertia_kg_m2;
    // Same rule as the rollout (src/sim/rollout.cpp, build_bodies): the body driven by the
    // first actuator carries the bench load.
    if (!model.actuators.empty() &&
        servo_law(actuator_servo_name(model, input.servo, 0)).point_mass_arm && !spec.is_static &&
        spec.parent_joint >= 0 && model.joints[spec.parent_joint].actuator1 == 0) {
      const JointSpec& joint = model.joints[spec.parent_joint];
      Eigen::Vector3d arm = spec.com_W0_m - joint.anchor_W0_m;
      arm -= joint.axis1_W0 * joint.axis1_W0.dot(arm);
      if (arm.norm() < 1e-9) throw ModelError("bench arm CoM lies on the joint axis");
      const ParameterSet& p = input.parameters;
      body.mass_kg = p.get("bench.mass_kg");
      body.com_m = joint.anchor_W0_m + arm.normalized() * p.get("bench.length_m");
      const double armature = p.get("bench.armature_kg_m2");
      body.inertia_kg_m2 =
          Eigen::Matrix3d::Identity() * (armature_in_bench_arm ? std::max(armature, 1e-9) : 1e-9);
    }
    body.com_m += offset_m;
  }
  return out;
}

Eigen::Vector3d placement_offset_m(const RobotModel& model,
                                   const std::vector<double>& actuator_angles_rad,
                                   double clearance_m) {
  if (model.fixed_base) return Eigen::Vector3d::Zero();
  const double lowest = lowest_foot_point_z(model, body_poses(model, actuator_angles_rad));
  if (!std::isfinite(lowest)) return Eigen::Vector3d::Zero();
  return {0.0, 0.0, clearance_m - lowest};
}

std::string export_header(const ExportInput& input, const std::string& target) {
  const std::string& source = input.provenance.source_path;
  return "Exported by motoflex " + std::string(version()) + target + " from " +
         (source.empty() ? std::string("defaults") : source) + "; servo " +
         servo_description(input);
}

std::string servo_description(const ExportInput& input) {
  // One law for the robot (the usual case), or the law of each joint.
  std::string description;
  std::string previous;
  for (std::size_t i = 0; i < input.model.actuators.size(); ++i) {
    const std::string& law = actuator_servo_name(input.model, input.servo, i);
    if (law == previous) continue;
    if (!description.empty()) description += "; " + input.model.actuators[i].name + ": ";
    description += servo_export_rule(law).description;
    previous = law;
  }
  return description;
}

}  // namespace motoflex::detail
