#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/model/geometry.hpp"
#include "motoflex/model/parameters.hpp"

namespace motoflex {

// Structural choices made when a robot is loaded (they change bodies and joints, not values).
struct StructureOptions {
  int flex_sub_bodies = 1;       // sub-bodies per flexible link (1 = rigid)
  bool universal_joints = true;  // merge declared hinge pairs into one ODE universal joint
};

// One ODE body. Body frames have their origin at the CoM and world orientation in the build
// configuration (actuated joints at 0, held joints at their hold angles, flex joints at 0).
struct BodySpec {
  std::string name;
  std::vector<std::string> links;  // URDF links lumped into this body
  double mass_kg = 0.0;
  Eigen::Matrix3d inertia_kg_m2 = Eigen::Matrix3d::Zero();  // about the CoM
  Eigen::Vector3d com_W0_m = Eigen::Vector3d::Zero();       // CoM in the build configuration
  std::vector<CollisionShape> collisions;
  std::vector<VisualShape> visuals;
  bool is_static = false;  // the welded base of a fixed-base robot: not an ODE body
  int parent_joint = -1;   // joint whose child this body is (−1 for the root)
};

enum class JointKind {
  kHinge,      // one revolute axis
  kUniversal,  // two orthogonal actuated axes through one point (axis1 parent side)
  kFlex,       // two bending axes between sub-bodies of a flexible link (springs)
  kSlider,     // one prismatic axis (URDF prismatic): positions in m, forces in N
};

// A URDF <mimic> follower: its position is held at multiplier·q_leader + offset by a stiff
// implicit coupling (the follower has no actuator and no stops of its own).
struct MimicSpec {
  int leader_joint = -1;  // index into RobotModel::joints
  int leader_axis = 1;    // 1 or 2 (a leader merged into a universal joint)
  double multiplier = 1.0;
  double offset = 0.0;  // rad or m, in the follower's unit
};

struct JointSpec {
  std::string name;
  JointKind kind = JointKind::kHinge;
  int parent_body = -1;
  int child_body = -1;
  Eigen::Vector3d anchor_W0_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d axis1_W0 = Eigen::Vector3d::UnitY();  // unit, world frame at build config
  Eigen::Vector3d axis2_W0 = Eigen::Vector3d::UnitX();  // second axis (universal, flex)
  // ODE stops (URDF limits, unless robot.yaml says joint_stops: false), m for a slider; infinite
  // when the URDF joint is unlimited.
  double lower1_rad = -std::numeric_limits<double>::infinity();
  double upper1_rad = std::numeric_limits<double>::infinity();
  double lower2_rad = -std::numeric_limits<double>::infinity();
  double upper2_rad = std::numeric_limits<double>::infinity();
  int actuator1 = -1;  // index into RobotModel::actuators driving axis 1, or −1
  int actuator2 = -1;
  std::optional<MimicSpec> mimic;  // a hinge or slider following another joint
};

// One actuated joint axis, in log column order.
struct ActuatorSpec {
  std::string name;   // URDF joint name, e.g. "LKneePitch"
  std::string group;  // gear / servo group from robot.yaml, e.g. "A"
  std::string servo;  // servo law of this joint; empty = the robot's default_servo
  // Prefix of this joint's servo parameters, `servo.<servo_scope>.<name>_<unit>`: the joint or
  // group named by its robot.yaml `servos:` entry (laws with per-joint/group parameters).
  std::string servo_scope;
  int joint = -1;  // index into RobotModel::joints
  int axis = 1;    // 1 or 2
  // A prismatic joint: positions in m, efforts in N, its parameters named in _m and _n.
  bool prismatic = false;
  // The URDF limits (rad or m), kept even when robot.yaml turns the stops off.
  double lower_rad = -std::numeric_limits<double>::infinity();
  double upper_rad = std::numeric_limits<double>::infinity();
  // What the URDF says about the joint (NaN when it says nothing): <limit effort velocity>
  // (N·m or N; rad/s or m/s) and <dynamics damping friction> (N·m·s/rad or N·s/m; N·m or N).
  // Raw values: placeholders (effort 0, velocity 1e6, ...) are judged by whoever uses them.
  double urdf_effort = std::numeric_limits<double>::quiet_NaN();
  double urdf_velocity = std::numeric_limits<double>::quiet_NaN();
  double urdf_damping = std::numeric_limits<double>::quiet_NaN();
  double urdf_friction = std::numeric_limits<double>::quiet_NaN();
};

// Everything constant about a robot. Built once, shared read-only by every rollout thread.
struct RobotModel {
  std::string name;
  std::string directory;  // folder of robot.yaml
  std::string urdf_path;
  // The servo law of robot.yaml's `servo:` (a name of the sim layer's registry, checked there).
  std::string default_servo = "ideal";
  StructureOptions structure;

  std::vector<BodySpec> bodies;
  std::vector<JointSpec> joints;        // topological order: a parent body precedes its children
  std::vector<ActuatorSpec> actuators;  // log column order
  bool fixed_base = false;
  // robot.yaml `joint_stops` (default true): false leaves the URDF limits out of the joints: no
  // ODE stops, no limits in SDF/MJCF exports; ActuatorSpec keeps them for motion planners.
  bool joint_stops = true;
  int root_body = 0;
  int torso_body = 0;
  Eigen::Matrix3d R_torsoBody_torsoLink = Eigen::Matrix3d::Identity();

  double max_tilt_rad = 1.0;
  double min_torso_height_m = 0.0;
  double initial_clearance_m = 0.001;
  // false: no ground plane (a robot mounted on a stand or table): nothing touches, nothing falls.
  bool ground = true;
  std::map<std::string, double> stand_pose_rad;  // actuated joint → angle (missing: 0)

  ParameterRegistry parameters;
  // Where robot.yaml declared what, so checks made after loading (the servo law's parameters,
  // in the sim layer) can still name the file and line.
  struct Source {
    std::string yaml_path;
    int servo_line = 0;
    std::map<std::string, int> servos_lines;  // robot.yaml `servos:` key → line
    int parameters_line = 0;
    std::map<std::string, int> parameter_lines;  // declared parameters only
  } source;

  std::optional<std::size_t> actuator_index(const std::string& joint_name) const;
  std::vector<std::string> actuator_names() const;
  // Stand pose in actuator order.
  std::vector<double> stand_pose_vector() const;
};

}  // namespace motoflex
