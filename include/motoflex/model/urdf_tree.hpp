#pragma once

// A URDF as a plain tree of links and joints, with everything motoflex reads from it: mass
// properties, collision and visual geometry (mesh files resolved, not loaded), joint frames,
// axes, limits, dynamics and mimic couplings. The loader lumps it into ODE bodies
// (robot_loader.hpp); `motoflex init-robot` reads it to write a robot folder.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/core/error_collector.hpp"
#include "motoflex/model/geometry.hpp"

namespace motoflex {

// Links at or below this mass (1 µg) are frame links: they carry no mass and are lumped into
// the body they are welded to. Real links must weigh more, up to kMaxLinkMass_kg.
inline constexpr double kFrameLinkMass_kg = 1e-9;
inline constexpr double kMaxLinkMass_kg = 1e4;  // 10 t
// Relative slack of the inertia triangle inequality I1 + I2 >= I3 (CAD exports round their
// inertias to a few digits, which can break it for thin plates by ~1e-6).
inline constexpr double kInertiaTriangleTolerance = 1e-3;

struct UrdfCollision {
  ShapeGeometry shape;
  Eigen::Isometry3d X_LG = Eigen::Isometry3d::Identity();  // shape pose in the link frame
  bool from_capsule_tag = false;  // written as <capsule> (accepted, read as a capsule)
};

struct UrdfVisual {
  ShapeGeometry shape;
  Eigen::Isometry3d X_LG = Eigen::Isometry3d::Identity();
  std::string material;
  std::optional<Eigen::Vector4d> rgba;
};

struct UrdfLink {
  std::string name;
  int line = 0;  // of its <link> element in the URDF
  bool has_inertial = false;
  double mass_kg = 0.0;
  Eigen::Vector3d com_L_m = Eigen::Vector3d::Zero();
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();  // about the CoM, link axes
  std::vector<UrdfCollision> collisions;
  std::vector<UrdfVisual> visuals;
  int parent_joint = -1;
  std::vector<int> child_joints;

  // No <inertial>, or a mass of at most kFrameLinkMass_kg: a coordinate frame, not a body.
  bool is_frame_link() const { return !has_inertial || mass_kg <= kFrameLinkMass_kg; }
};

enum class UrdfJointType {
  kRevolute,   // revolute and continuous (continuous: `limited` false)
  kPrismatic,  // translation along the axis (m)
  kFixed,      // welds the child to the parent
  kFlex,       // motoflex's own: a bending joint inside a split flexible link
  kFloating,   // only as the root's single joint to a free base (then skipped)
  kPlanar,     // rejected when read
};

struct UrdfMimic {
  std::string joint;  // the leader
  double multiplier = 1.0;
  double offset = 0.0;
};

struct UrdfJoint {
  std::string name;
  int line = 0;
  UrdfJointType type = UrdfJointType::kFixed;
  bool continuous = false;  // URDF type "continuous" (a revolute joint without limits)
  int parent_link = -1;
  int child_link = -1;
  Eigen::Isometry3d X_PJ = Eigen::Isometry3d::Identity();  // joint frame in the parent link
  Eigen::Vector3d axis_J = Eigen::Vector3d::UnitZ();       // unit axis in the joint frame
  Eigen::Vector3d axis2_J = Eigen::Vector3d::UnitX();      // second bending axis (flex only)
  double lower_rad = 0.0;                                  // m for a prismatic joint
  double upper_rad = 0.0;
  bool limited = false;
  // <limit effort velocity> and <dynamics damping friction>; NaN when absent.
  double effort = std::numeric_limits<double>::quiet_NaN();
  double velocity = std::numeric_limits<double>::quiet_NaN();
  double damping = std::numeric_limits<double>::quiet_NaN();
  double friction = std::numeric_limits<double>::quiet_NaN();
  std::optional<UrdfMimic> mimic;

  bool movable() const {
    return type == UrdfJointType::kRevolute || type == UrdfJointType::kPrismatic;
  }
};

struct UrdfTree {
  std::string path;  // the URDF file
  std::string robot_name;
  // Links and joints sorted by name (urdfdom's order, which fixes the ODE body order).
  std::vector<UrdfLink> links;
  std::vector<UrdfJoint> joints;
  std::vector<std::string> joint_document_order;  // joint names as the file lists them
  int root_link = 0;  // the base: the URDF's root, or the child of a floating root joint

  int link_index(const std::string& name) const;   // −1 if absent
  int joint_index(const std::string& name) const;  // −1 if absent
};

// Reads a URDF. A file that cannot be parsed at all (missing, not XML, not a tree) throws
// InputError naming the file and line. Problems of single links and joints (an implausible
// inertia, a mesh file that cannot be found, a planar joint, a <capsule> without a size) are
// added to `errors`, each naming the file, line and element, and the tree is returned without
// the offending part. Meshes are located (package:// and relative paths, see
// resolve_mesh_path) but not loaded.
UrdfTree read_urdf_tree(const std::string& urdf_path, ErrorCollector& errors);

// The mesh file a URDF's `filename` refers to: `package://pkg/rest` is looked up as
// <ancestor>/rest for every ancestor folder of the URDF named `pkg`, then as
// <ancestor>/pkg/rest and <ancestor>/rest for every ancestor; `file://` is a path; a relative
// path is relative to the URDF's folder. Empty when no such file exists.
std::string resolve_mesh_path(const std::string& uri, const std::string& urdf_path);

}  // namespace motoflex
