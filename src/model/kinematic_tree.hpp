#pragma once

// Internal to the model loader: a URDF as a plain tree of links and joints, which can be
// edited (flexible links split into sub-links) before it is lumped into ODE bodies.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

namespace motoflex::detail {

struct TreeBox {
  Eigen::Vector3d size_m;
  Eigen::Isometry3d X_LG;  // box pose in the link frame
};

struct TreeLink {
  std::string name;
  double mass_kg = 0.0;
  Eigen::Vector3d com_L_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();  // about the CoM, link axes
  std::vector<TreeBox> boxes;
  int parent_joint = -1;
  std::vector<int> child_joints;
};

enum class TreeJointType { kRevolute, kFixed, kFlex };

struct TreeJoint {
  std::string name;
  TreeJointType type = TreeJointType::kFixed;
  int parent_link = -1;
  int child_link = -1;
  Eigen::Isometry3d X_PJ = Eigen::Isometry3d::Identity();  // joint frame in the parent link
  Eigen::Vector3d axis_J = Eigen::Vector3d::UnitZ();       // unit axis in the joint frame
  Eigen::Vector3d axis2_J = Eigen::Vector3d::UnitX();      // second bending axis (flex only)
  double lower_rad = 0.0;
  double upper_rad = 0.0;
  bool limited = false;
};

struct KinematicTree {
  std::vector<TreeLink> links;
  std::vector<TreeJoint> joints;
  int root_link = 0;

  int link_index(const std::string& name) const;   // −1 if absent
  int joint_index(const std::string& name) const;  // −1 if absent
};

// Parses a URDF with urdfdom. Throws InputError naming the file (and, where it can be found,
// the line of the offending element) for parse errors and unsupported joint types.
KinematicTree load_urdf_tree(const std::string& urdf_path);

// Splits `link` into `pieces` equal sub-links along the vector from its origin to its child
// joint, joined by kFlex joints bending about the two axes orthogonal to that vector. Mass,
// CoM and inertia of the whole are preserved. Throws std::invalid_argument if the link does
// not have exactly one child joint.
void split_flexible_link(KinematicTree& tree, const std::string& link, int pieces);

// Splits `link`, a single homogeneous box (the 2011 program's legs, motoflex_2011.md §2.9), into
// `pieces` equal boxes stacked along the box axis closest to the vector from the link's origin
// to its child joint, joined by kFlex joints where their faces meet; each piece has a box's
// inertia. Throws std::invalid_argument unless the link has exactly one child joint and one box.
void split_flexible_box(KinematicTree& tree, const std::string& link, int pieces);

// World pose of every link for the given joint angles (radians by joint index; fixed and flex
// joints ignore their entry).
std::vector<Eigen::Isometry3d> link_poses(const KinematicTree& tree,
                                          const std::vector<double>& joint_angles_rad);

// Inertia tensor shift: m·(|d|²·1 − d·dᵀ).
Eigen::Matrix3d parallel_axis(double mass_kg, const Eigen::Vector3d& d_m);

}  // namespace motoflex::detail
