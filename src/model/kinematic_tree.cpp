#include "kinematic_tree.hpp"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace motoflex {

int UrdfTree::link_index(const std::string& name) const {
  for (std::size_t i = 0; i < links.size(); ++i) {
    if (links[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

int UrdfTree::joint_index(const std::string& name) const {
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

namespace detail {
namespace {

// An orthonormal pair perpendicular to `along`, preferring the link's own x and y axes.
std::pair<Eigen::Vector3d, Eigen::Vector3d> bending_axes(const Eigen::Vector3d& along) {
  const Eigen::Vector3d s = along.normalized();
  Eigen::Vector3d first = Eigen::Vector3d::UnitX() - s * s.x();
  if (first.norm() < 0.5) first = Eigen::Vector3d::UnitY() - s * s.y();
  first.normalize();
  return {first, s.cross(first).normalized()};
}

// The piece of a link split into `pieces` along `span` that holds a point at `p_L`.
int piece_holding(const Eigen::Vector3d& p_L, const Eigen::Vector3d& span, int pieces) {
  const double along = p_L.dot(span) / span.squaredNorm();
  return std::clamp(static_cast<int>(std::floor(along * pieces)), 0, pieces - 1);
}

}  // namespace

Eigen::Matrix3d parallel_axis(double mass_kg, const Eigen::Vector3d& d_m) {
  return mass_kg * (d_m.squaredNorm() * Eigen::Matrix3d::Identity() - d_m * d_m.transpose());
}

std::vector<int> links_breadth_first(const UrdfTree& tree, int root) {
  std::vector<int> order{root};
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (const int j : tree.links[order[i]].child_joints) {
      if (tree.joints[j].type == UrdfJointType::kFloating) continue;
      order.push_back(tree.joints[j].child_link);
    }
  }
  return order;
}

void split_flexible_link(UrdfTree& tree, const std::string& link_name, int pieces) {
  if (pieces <= 1) return;
  const int link_id = tree.link_index(link_name);
  if (link_id < 0) throw std::invalid_argument("flexible link '" + link_name + "' not in URDF");
  if (tree.links[link_id].child_joints.size() != 1) {
    throw std::invalid_argument("flexible link '" + link_name +
                                "' must have exactly one child joint to be split");
  }
  const UrdfLink whole = tree.links[link_id];
  const int child_joint = whole.child_joints.front();
  const Eigen::Vector3d span = tree.joints[child_joint].X_PJ.translation();
  if (span.norm() < 1e-6) {
    throw std::invalid_argument("flexible link '" + link_name + "' has zero length");
  }
  const auto [bend1, bend2] = bending_axes(span);
  const double piece_mass = whole.mass_kg / pieces;

  // Piece k spans [k/N, (k+1)/N] of the link; its frame is the link frame shifted by k/N·span.
  std::vector<Eigen::Vector3d> com(pieces);
  Eigen::Matrix3d spread = Eigen::Matrix3d::Zero();
  for (int k = 0; k < pieces; ++k) {
    const double offset = (k + 0.5) / pieces - 0.5;
    com[k] = whole.com_L_m + offset * span;
    spread += parallel_axis(piece_mass, com[k] - whole.com_L_m);
  }
  // Equal share of what the spread of the pieces does not already account for; keeps the total
  // inertia about the CoM exact when that remainder is positive definite.
  Eigen::Matrix3d piece_inertia = (whole.inertia_kg_m2 - spread) / pieces;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(piece_inertia);
  Eigen::Vector3d eig = solver.eigenvalues();
  const double floor = 1e-3 * std::max(whole.inertia_kg_m2.trace() / 3.0 / pieces, 1e-12);
  if (eig.minCoeff() < floor) {
    eig = eig.cwiseMax(floor);
    piece_inertia = solver.eigenvectors() * eig.asDiagonal() * solver.eigenvectors().transpose();
  }

  std::vector<int> ids(pieces);
  ids[0] = link_id;
  for (int k = 1; k < pieces; ++k) {
    ids[k] = static_cast<int>(tree.links.size());
    UrdfLink piece;
    piece.name = link_name + "#" + std::to_string(k);
    tree.links.push_back(piece);
  }
  for (int k = 0; k < pieces; ++k) {
    UrdfLink& piece = tree.links[ids[k]];
    const Eigen::Vector3d origin = (static_cast<double>(k) / pieces) * span;
    piece.has_inertial = whole.has_inertial;
    piece.mass_kg = piece_mass;
    piece.com_L_m = com[k] - origin;
    piece.inertia_kg_m2 = piece_inertia;
    piece.collisions.clear();
    piece.visuals.clear();
    piece.child_joints.clear();
  }
  // Each shape goes to the piece that contains its origin along the span.
  for (UrdfCollision shape : whole.collisions) {
    const int k = piece_holding(shape.X_LG.translation(), span, pieces);
    shape.X_LG.translation() -= (static_cast<double>(k) / pieces) * span;
    tree.links[ids[k]].collisions.push_back(std::move(shape));
  }
  for (UrdfVisual shape : whole.visuals) {
    const int k = piece_holding(shape.X_LG.translation(), span, pieces);
    shape.X_LG.translation() -= (static_cast<double>(k) / pieces) * span;
    tree.links[ids[k]].visuals.push_back(std::move(shape));
  }
  for (int k = 1; k < pieces; ++k) {
    UrdfJoint flex;
    flex.name = link_name + "#flex" + std::to_string(k);
    flex.type = UrdfJointType::kFlex;
    flex.parent_link = ids[k - 1];
    flex.child_link = ids[k];
    flex.X_PJ = Eigen::Isometry3d::Identity();
    flex.X_PJ.translation() = span / pieces;
    flex.axis_J = bend1;
    flex.axis2_J = bend2;
    const int flex_id = static_cast<int>(tree.joints.size());
    tree.joints.push_back(flex);
    tree.links[ids[k - 1]].child_joints.push_back(flex_id);
    tree.links[ids[k]].parent_joint = flex_id;
  }
  UrdfJoint& original_child = tree.joints[child_joint];
  original_child.parent_link = ids[pieces - 1];
  original_child.X_PJ.translation() -= (static_cast<double>(pieces - 1) / pieces) * span;
  tree.links[ids[pieces - 1]].child_joints.push_back(child_joint);
}

std::vector<Eigen::Isometry3d> link_poses(const UrdfTree& tree,
                                          const std::vector<double>& joint_positions) {
  std::vector<Eigen::Isometry3d> poses(tree.links.size(), Eigen::Isometry3d::Identity());
  std::vector<int> stack{tree.root_link};
  while (!stack.empty()) {
    const int link = stack.back();
    stack.pop_back();
    for (const int j : tree.links[link].child_joints) {
      const UrdfJoint& joint = tree.joints[j];
      if (joint.type == UrdfJointType::kFloating) continue;
      Eigen::Isometry3d X = poses[link] * joint.X_PJ;
      if (joint.type == UrdfJointType::kRevolute) {
        X.rotate(Eigen::AngleAxisd(joint_positions.at(j), joint.axis_J));
      } else if (joint.type == UrdfJointType::kPrismatic) {
        X.translate(joint_positions.at(j) * joint.axis_J);
      }
      poses[joint.child_link] = X;
      stack.push_back(joint.child_link);
    }
  }
  return poses;
}

}  // namespace detail
}  // namespace motoflex
