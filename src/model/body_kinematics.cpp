#include "motoflex/model/body_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace motoflex {
namespace {

double lowest_vertex_z(const std::vector<double>& xyz, const Eigen::Isometry3d& X_WG) {
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3) {
    lowest = std::min(lowest, (X_WG * Eigen::Vector3d(xyz[i], xyz[i + 1], xyz[i + 2])).z());
  }
  return lowest;
}

// Position of each model joint's axes (rad or m): actuated axes from the pose, passive ones 0,
// mimic followers from their leader.
std::vector<std::pair<double, double>> joint_positions(const RobotModel& model,
                                                       const std::vector<double>& pose) {
  std::vector<std::pair<double, double>> q(model.joints.size(), {0.0, 0.0});
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const JointSpec& joint = model.joints[j];
    if (joint.actuator1 >= 0) q[j].first = pose.at(joint.actuator1);
    if (joint.actuator2 >= 0) q[j].second = pose.at(joint.actuator2);
  }
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const auto& mimic = model.joints[j].mimic;
    if (!mimic) continue;
    const auto& leader = q[mimic->leader_joint];
    q[j].first = mimic->multiplier * (mimic->leader_axis == 1 ? leader.first : leader.second) +
                 mimic->offset;
  }
  return q;
}

}  // namespace

std::vector<Eigen::Isometry3d> body_poses(const RobotModel& model,
                                          const std::vector<double>& actuator_positions) {
  std::vector<Eigen::Isometry3d> poses(model.bodies.size(), Eigen::Isometry3d::Identity());
  poses[model.root_body].translation() = model.bodies[model.root_body].com_W0_m;
  const auto q = joint_positions(model, actuator_positions);
  // Joints are stored parents-first; every body frame has world orientation at build config,
  // so a joint's axes and anchor, read in the parent frame, are its build-config world values.
  for (std::size_t j = 0; j < model.joints.size(); ++j) {
    const JointSpec& joint = model.joints[j];
    const BodySpec& parent = model.bodies[joint.parent_body];
    const BodySpec& child = model.bodies[joint.child_body];
    const auto [q1, q2] = q[j];
    const Eigen::Vector3d anchor_P = joint.anchor_W0_m - parent.com_W0_m;
    Eigen::Isometry3d X_PC = Eigen::Isometry3d::Identity();
    if (joint.kind == JointKind::kSlider) {
      X_PC.translation() = anchor_P + (child.com_W0_m - joint.anchor_W0_m) + q1 * joint.axis1_W0;
    } else {
      Eigen::Matrix3d R = Eigen::AngleAxisd(q1, joint.axis1_W0).toRotationMatrix();
      if (joint.kind != JointKind::kHinge) R = R * Eigen::AngleAxisd(q2, joint.axis2_W0);
      X_PC.linear() = R;
      X_PC.translation() = anchor_P + R * (child.com_W0_m - joint.anchor_W0_m);
    }
    poses[joint.child_body] = poses[joint.parent_body] * X_PC;
  }
  return poses;
}

double lowest_point_z(const CollisionShape& shape, const Eigen::Isometry3d& X_WB) {
  const Eigen::Isometry3d X_WG = X_WB * shape.X_BG;
  const double center_z = X_WG.translation().z();
  // |z component| of the shape's axis; the rim of a disc of radius r about that axis reaches
  // r·sqrt(1 − a_z²) lower than its centre.
  const double axis_z = std::abs(X_WG.linear()(2, 2));
  const double half_length = 0.5 * shape.length_m;
  switch (shape.kind) {
    case ShapeKind::kBox: {
      double lowest = std::numeric_limits<double>::infinity();
      for (int corner = 0; corner < 8; ++corner) {
        const Eigen::Vector3d local(((corner & 1) ? 0.5 : -0.5) * shape.size_m.x(),
                                    ((corner & 2) ? 0.5 : -0.5) * shape.size_m.y(),
                                    ((corner & 4) ? 0.5 : -0.5) * shape.size_m.z());
        lowest = std::min(lowest, (X_WG * local).z());
      }
      return lowest;
    }
    case ShapeKind::kSphere:
      return center_z - shape.radius_m;
    case ShapeKind::kCylinder:
      return center_z - half_length * axis_z -
             shape.radius_m * std::sqrt(std::max(0.0, 1.0 - axis_z * axis_z));
    case ShapeKind::kCapsule:
      return center_z - half_length * axis_z - shape.radius_m;
    case ShapeKind::kMesh:
      if (shape.hull) return lowest_vertex_z(shape.hull->points_m, X_WG);
      if (shape.trimesh) return lowest_vertex_z(shape.trimesh->vertices_m, X_WG);
      return std::numeric_limits<double>::infinity();
  }
  return std::numeric_limits<double>::infinity();
}

double lowest_foot_point_z(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses) {
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    for (const CollisionShape& shape : model.bodies[b].collisions) {
      if (shape.is_foot) lowest = std::min(lowest, lowest_point_z(shape, poses[b]));
    }
  }
  return lowest;
}

double lowest_shape_point_z(const RobotModel& model, const std::vector<Eigen::Isometry3d>& poses) {
  double lowest = std::numeric_limits<double>::infinity();
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    for (const CollisionShape& shape : model.bodies[b].collisions) {
      lowest = std::min(lowest, lowest_point_z(shape, poses[b]));
    }
  }
  return lowest;
}

}  // namespace motoflex
