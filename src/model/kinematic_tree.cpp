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

// Replaces link `link_id` by `parts` (part 0 keeps its id and name), part k's frame at
// `origins[k]` in the link frame (link axes), joined in a chain by kFlex joints (joint k at
// `steps[k]` in part k−1's frame) that bend about the axes orthogonal to `span`; the link's
// child joint moves to the last part.
void wire_pieces(UrdfTree& tree, int link_id, int child_joint, std::vector<UrdfLink>& parts,
                 const std::vector<Eigen::Vector3d>& origins,
                 const std::vector<Eigen::Vector3d>& steps, const Eigen::Vector3d& span) {
  const int pieces = static_cast<int>(parts.size());
  const UrdfLink whole = tree.links[link_id];
  const auto [bend1, bend2] = bending_axes(span);
  std::vector<int> ids(pieces);
  ids[0] = link_id;
  for (int k = 1; k < pieces; ++k) {
    ids[k] = static_cast<int>(tree.links.size());
    tree.links.emplace_back();
  }
  for (int k = 0; k < pieces; ++k) {
    parts[k].name = k == 0 ? whole.name : whole.name + "#" + std::to_string(k);
    parts[k].line = whole.line;
    parts[k].has_inertial = whole.has_inertial;
    parts[k].parent_joint = k == 0 ? whole.parent_joint : -1;
    parts[k].child_joints.clear();
    tree.links[ids[k]] = parts[k];
  }
  for (int k = 1; k < pieces; ++k) {
    UrdfJoint flex;
    flex.name = whole.name + "#flex" + std::to_string(k);
    flex.type = UrdfJointType::kFlex;
    flex.parent_link = ids[k - 1];
    flex.child_link = ids[k];
    flex.X_PJ = Eigen::Isometry3d::Identity();
    flex.X_PJ.translation() = steps[k];
    flex.axis_J = bend1;
    flex.axis2_J = bend2;
    const int flex_id = static_cast<int>(tree.joints.size());
    tree.joints.push_back(flex);
    tree.links[ids[k - 1]].child_joints.push_back(flex_id);
    tree.links[ids[k]].parent_joint = flex_id;
  }
  UrdfJoint& original_child = tree.joints[child_joint];
  original_child.parent_link = ids[pieces - 1];
  original_child.X_PJ.translation() -= origins[pieces - 1];
  tree.links[ids[pieces - 1]].child_joints.push_back(child_joint);
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

  std::vector<UrdfLink> parts(pieces);
  std::vector<Eigen::Vector3d> origins(pieces);
  for (int k = 0; k < pieces; ++k) {
    origins[k] = (static_cast<double>(k) / pieces) * span;
    parts[k].mass_kg = piece_mass;
    parts[k].com_L_m = com[k] - origins[k];
    parts[k].inertia_kg_m2 = piece_inertia;
  }
  // Each shape goes to the piece that contains its origin along the span.
  for (UrdfCollision shape : whole.collisions) {
    const int k = piece_holding(shape.X_LG.translation(), span, pieces);
    shape.X_LG.translation() -= origins[k];
    parts[k].collisions.push_back(std::move(shape));
  }
  for (UrdfVisual shape : whole.visuals) {
    const int k = piece_holding(shape.X_LG.translation(), span, pieces);
    shape.X_LG.translation() -= origins[k];
    parts[k].visuals.push_back(std::move(shape));
  }
  const std::vector<Eigen::Vector3d> steps(pieces, span / pieces);
  wire_pieces(tree, link_id, child_joint, parts, origins, steps, span);
}

void split_flexible_box(UrdfTree& tree, const std::string& link_name, int pieces) {
  if (pieces <= 1) return;
  const int link_id = tree.link_index(link_name);
  if (link_id < 0) throw std::invalid_argument("flexible link '" + link_name + "' not in URDF");
  const UrdfLink whole = tree.links[link_id];
  if (whole.child_joints.size() != 1 || whole.collisions.size() != 1 ||
      whole.collisions.front().shape.kind != ShapeKind::kBox) {
    throw std::invalid_argument("flexible link '" + link_name +
                                "' must have exactly one child joint and one box to be split");
  }
  const Eigen::Vector3d span = tree.joints[whole.child_joints.front()].X_PJ.translation();
  if (span.norm() < 1e-6) {
    throw std::invalid_argument("flexible link '" + link_name + "' has zero length");
  }
  // The box's own axis closest to the span is the stacking direction.
  const UrdfCollision& box = whole.collisions.front();
  int stack_axis = 0;
  for (int i = 1; i < 3; ++i) {
    if (std::abs(box.X_LG.linear().col(i).dot(span)) >
        std::abs(box.X_LG.linear().col(stack_axis).dot(span))) {
      stack_axis = i;
    }
  }
  Eigen::Vector3d direction = box.X_LG.linear().col(stack_axis);
  if (direction.dot(span) < 0.0) direction = -direction;
  const double height_m = box.shape.size_m[stack_axis];
  Eigen::Vector3d piece_size = box.shape.size_m;
  piece_size[stack_axis] = height_m / pieces;
  const double piece_mass = whole.mass_kg / pieces;
  // A homogeneous box's inertia about its centre, in the link axes.
  const Eigen::Vector3d s2 = piece_size.cwiseProduct(piece_size);
  const Eigen::Matrix3d local =
      Eigen::Vector3d(s2.y() + s2.z(), s2.x() + s2.z(), s2.x() + s2.y()).asDiagonal() *
      (piece_mass / 12.0);
  const Eigen::Matrix3d piece_inertia = box.X_LG.linear() * local * box.X_LG.linear().transpose();

  std::vector<UrdfLink> parts(pieces);
  std::vector<Eigen::Vector3d> origins(pieces, Eigen::Vector3d::Zero());
  const Eigen::Vector3d near_face = box.X_LG.translation() - 0.5 * height_m * direction;
  for (int k = 0; k < pieces; ++k) {
    // Piece k's frame sits on its face toward the link origin (the link frame for piece 0):
    // the bending joint between two pieces is where their faces meet.
    if (k > 0) origins[k] = near_face + (static_cast<double>(k) / pieces) * height_m * direction;
    const Eigen::Vector3d centre = near_face + ((k + 0.5) / pieces) * height_m * direction;
    parts[k].mass_kg = piece_mass;
    parts[k].com_L_m = centre - origins[k];
    parts[k].inertia_kg_m2 = piece_inertia;
    UrdfCollision piece_box = box;
    piece_box.shape.size_m = piece_size;
    piece_box.X_LG.translation() = centre - origins[k];
    parts[k].collisions.push_back(piece_box);
  }
  // Each visual goes to the piece whose slice of the box holds its origin.
  for (UrdfVisual shape : whole.visuals) {
    const double along = (shape.X_LG.translation() - near_face).dot(direction) / height_m;
    const int k = std::clamp(static_cast<int>(std::floor(along * pieces)), 0, pieces - 1);
    shape.X_LG.translation() -= origins[k];
    parts[k].visuals.push_back(std::move(shape));
  }
  std::vector<Eigen::Vector3d> steps(pieces, Eigen::Vector3d::Zero());
  for (int k = 1; k < pieces; ++k) steps[k] = origins[k] - origins[k - 1];
  wire_pieces(tree, link_id, whole.child_joints.front(), parts, origins, steps, span);
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
