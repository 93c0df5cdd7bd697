#include "motoflex/sim/actuator/stance_gains.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "motoflex/model/body_kinematics.hpp"

namespace motoflex {
namespace {

constexpr double kGravity_m_s2 = 9.81;

// Three significant digits: starting values a user reads in robot.yaml, not derived exactly.
double three_digits(double value) {
  if (!(value > 0.0)) return value;
  const double scale = std::pow(10.0, std::floor(std::log10(value)) - 2.0);
  return std::round(value / scale) * scale;
}

// Whether `body` lies below `joint` (the joint's child or one of its descendants).
bool below(const RobotModel& model, int body, int joint) {
  for (int b = body; b >= 0;) {
    const int parent_joint = model.bodies[b].parent_joint;
    if (parent_joint < 0) return false;
    if (parent_joint == joint) return true;
    b = model.joints[parent_joint].parent_body;
  }
  return false;
}

}  // namespace

std::optional<StanceGains> stance_gains(const RobotModel& model, std::size_t actuator) {
  const ActuatorSpec& spec = model.actuators.at(actuator);
  if (model.fixed_base || spec.prismatic) return std::nullopt;
  double mass_kg = 0.0;
  std::set<std::string> feet;
  for (const BodySpec& body : model.bodies) {
    mass_kg += body.mass_kg;
    for (const CollisionShape& shape : body.collisions) {
      if (shape.is_foot) feet.insert(shape.link.substr(0, shape.link.find('#')));
    }
  }
  if (feet.empty() || !(mass_kg > 0.0)) return std::nullopt;

  const std::vector<Eigen::Isometry3d> poses = body_poses(model, model.stand_pose_vector());
  const JointSpec& joint = model.joints[spec.joint];
  const BodySpec& child = model.bodies[joint.child_body];
  const Eigen::Vector3d anchor_W = poses[joint.child_body] * (joint.anchor_W0_m - child.com_W0_m);
  double lever_m = 0.0;
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    if (!below(model, static_cast<int>(b), spec.joint)) continue;
    for (const CollisionShape& shape : model.bodies[b].collisions) {
      if (!shape.is_foot) continue;
      const Eigen::Vector3d foot_W = poses[b] * shape.X_BG.translation();
      lever_m = std::max(lever_m, (foot_W - anchor_W).norm());
    }
  }
  if (!(lever_m > 0.0)) return std::nullopt;

  const double share_kg = mass_kg / static_cast<double>(feet.size());
  StanceGains out;
  out.lever_m = lever_m;
  out.hold_torque_nm = share_kg * kGravity_m_s2 * lever_m;
  out.kp_nm_per_rad = three_digits(out.hold_torque_nm / kStanceSag_rad);
  out.kd_nm_s_per_rad = three_digits(2.0 * kStanceDampingRatio *
                                     std::sqrt(out.kp_nm_per_rad * share_kg * lever_m * lever_m));
  out.torque_max_nm = three_digits(kStanceTorqueMargin * out.hold_torque_nm);
  return out;
}

}  // namespace motoflex
