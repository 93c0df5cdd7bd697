#pragma once

// Internal to the model loader: which URDF links become one ODE body (welded by fixed or held
// joints, or merged between the two axes of a universal joint), and the bodies built from
// them.

#include <Eigen/Geometry>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/model/urdf_tree.hpp"
#include "robot_yaml.hpp"

namespace motoflex::detail {

struct Lumping {
  std::vector<int> order;               // links below the base, breadth first (parents first)
  std::vector<int> body_of_link;        // body index per URDF link (−1: not below the base)
  std::map<int, int> universal_second;  // first joint → second joint of each merged pair
  std::set<int> merged_second_joints;   // the second joints (no joint of their own)
};

// Groups the links: fixed and held joints weld, a merged universal pair lumps the link between
// its axes into the second axis's child. Bodies are numbered in breadth-first order of their
// first link, the base first.
Lumping lump_links(const UrdfTree& tree, const RobotYaml& spec, bool merge_universal_pairs);

// The bodies of `lumping`: mass, CoM and inertia about it (frame links add nothing), and
// every collision and visual shape in the body frame with its ground-contact role (feet,
// contact_links; capsule_links turn <cylinder>s into capsules; trimesh_links keep meshes as
// trimeshes, other meshes become convex hulls). X_WL is every link's pose in the build
// configuration. Problems (a massless body behind a movable joint, an unreadable mesh) go to
// `errors`.
std::vector<BodySpec> build_bodies(const UrdfTree& tree, const Lumping& lumping,
                                   const std::vector<Eigen::Isometry3d>& X_WL,
                                   const RobotYaml& spec, ErrorCollector& errors);

}  // namespace motoflex::detail
