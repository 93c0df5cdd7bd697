#pragma once

// Internal to the model loader: edits and kinematics of a URDF tree (urdf_tree.hpp) before it
// is lumped into ODE bodies.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <string>
#include <vector>

#include "motoflex/model/urdf_tree.hpp"

namespace motoflex::detail {

// Splits `link` into `pieces` equal sub-links along the vector from its origin to its child
// joint, joined by kFlex joints bending about the two axes orthogonal to that vector. Mass,
// CoM and inertia of the whole are preserved; each collision and visual shape goes to the
// piece that holds its origin. Throws std::invalid_argument if the link does not have exactly
// one child joint.
void split_flexible_link(UrdfTree& tree, const std::string& link, int pieces);

// Splits `link`, a single homogeneous box (the 2011 program's legs, motoflex_2011.md §2.9), into
// `pieces` equal boxes stacked along the box axis closest to the vector from the link's origin
// to its child joint, joined by kFlex joints where their faces meet; each piece has a box's
// inertia. Throws std::invalid_argument unless the link has exactly one child joint and its
// only collision shape is a box.
void split_flexible_box(UrdfTree& tree, const std::string& link, int pieces);

// World pose of every link for the given joint positions (rad or m by joint index; fixed,
// flex and floating joints ignore their entry). Links not below the root keep the identity.
std::vector<Eigen::Isometry3d> link_poses(const UrdfTree& tree,
                                          const std::vector<double>& joint_positions);

// Inertia tensor shift: m·(|d|²·1 − d·dᵀ).
Eigen::Matrix3d parallel_axis(double mass_kg, const Eigen::Vector3d& d_m);

// The links below `root` (itself included), breadth first in child-joint order: every parent
// precedes its children.
std::vector<int> links_breadth_first(const UrdfTree& tree, int root);

}  // namespace motoflex::detail
