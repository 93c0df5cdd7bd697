#pragma once

#include <Eigen/Core>
#include <array>
#include <stdexcept>
#include <string>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

enum class LegSide { kLeft, kRight };
const char* to_string(LegSide side);  // "left" / "right"

// The five actuated joints of one Nao leg with HipYawPitch held at 0, in the order of the
// chain (and of the model's actuator list per leg): index into NaoLegAngles.
namespace nao_leg {
enum Joint : int { kHipRoll = 0, kHipPitch, kKneePitch, kAnklePitch, kAnkleRoll };
inline constexpr std::array<const char*, 5> kJointNames = {"HipRoll", "HipPitch", "KneePitch",
                                                           "AnklePitch", "AnkleRoll"};
}  // namespace nao_leg

// Which joint limits bound a Nao leg's inverse kinematics in motion planning.
enum class NaoJointLimits {
  kUrdf,   // always the URDF's (the real Nao's ranges), whatever the simulation does with them
  kStops,  // the URDF's only when the robot simulates them as stops (robot.yaml joint_stops);
           // a robot without stops (the 2011 MoToFlex box robot) is bounded by its leg only
};

// Leg dimensions (nao.md §1.1, scenarios/robots/nao/nao.urdf) and the URDF joint limits
// (nao.md §1.2; the right leg's limits are the mirror of the left ones except the slightly
// asymmetric right ankle pitch).
struct NaoLegGeometry {
  double hip_offset_y_m = 0.05;    // HipOffsetY: torso origin → hip joint, ±y
  double hip_offset_z_m = 0.085;   // HipOffsetZ: hip joint below the torso origin
  double thigh_m = 0.100;          // ThighLength: hip → knee
  double tibia_m = 0.1029;         // TibiaLength: knee → ankle
  double foot_height_m = 0.04519;  // FootHeight: ankle → sole along the foot's z
  // [joint][0 = lower, 1 = upper] in rad, joints in nao_leg::Joint order.
  std::array<std::array<double, 2>, 5> left_limits_rad = {{{-0.379435, 0.79046},
                                                           {-1.53589, 0.48398},
                                                           {-0.0923279, 2.11255},
                                                           {-1.18944, 0.922581},
                                                           {-0.397761, 0.768992}}};
  std::array<std::array<double, 2>, 5> right_limits_rad = {{{-0.79046, 0.379435},
                                                            {-1.53589, 0.48398},
                                                            {-0.0923279, 2.11255},
                                                            {-1.1863, 0.932006},
                                                            {-0.768992, 0.397761}}};

  // The limits are the URDF's on a robot that does not simulate them as stops (of() with
  // NaoJointLimits::kUrdf): a limit error then names the planner option that plans without them.
  bool limits_without_stops = false;

  const std::array<std::array<double, 2>, 5>& limits(LegSide side) const {
    return side == LegSide::kLeft ? left_limits_rad : right_limits_rad;
  }
  double leg_length_m() const { return thigh_m + tibia_m; }
  // Hip joint (HipRoll/HipPitch axes' intersection) in the torso frame.
  Eigen::Vector3d hip_in_torso_m(LegSide side) const;
  // The same geometry with the joint limits of the model's actuators ("LHipRoll", ...); throws
  // std::invalid_argument if the model lacks one of the ten leg actuators.
  static NaoLegGeometry with_limits_of(const RobotModel& model);
  // with_limits_of(model) with the model's own leg: hip_offset_y_m, thigh_m and tibia_m from the
  // left leg's joint anchors, foot_height_m from the AnkleRoll anchor down to the lowest foot
  // box corner, at the zero pose, each rounded to 1 nm (the URDFs give 0.1 mm; the rounding
  // removes the last bits of the anchor differences, so the Nao's lengths come out as the
  // defaults above, exactly). hip_offset_z_m stays: it places the torso frame, a convention.
  // The 2011 MoToFlex box robot has tibia 0.100 m and foot height 0.046 m (nao.md §3.2).
  // With NaoJointLimits::kStops and a model without joint stops every limit is infinite.
  static NaoLegGeometry of(const RobotModel& model, NaoJointLimits limits = NaoJointLimits::kUrdf);
};

using NaoLegAngles = std::array<double, 5>;  // rad, nao_leg::Joint order

// Pose of a foot's sole point relative to the torso frame (x forward, y left, z up). The sole
// point is `foot_height_m` below the ankle along the foot's z axis (the URDF's l_sole/r_sole).
// The orientation is given as Z-Y-X angles: R = Rz(yaw)·Ry(pitch)·Rx(roll).
struct NaoFootPose {
  Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
  double roll_rad = 0.0;
  double pitch_rad = 0.0;
  double yaw_rad = 0.0;
};

// A foot pose the leg cannot reach. The message names the side and the limit that was hit
// (the leg length, a joint's URDF limits, or the missing HipYawPitch freedom).
class NaoLegUnreachable : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

// Forward kinematics: sole pose in the torso frame for the five joint angles (HipYawPitch = 0).
// Angles outside the joint limits are evaluated as given.
NaoFootPose nao_leg_forward(LegSide side, const NaoLegAngles& angles_rad,
                            const NaoLegGeometry& geometry = {});

// Analytic inverse kinematics (knee-forward branch, KneePitch >= 0): the five joint angles that
// put the sole at `target`. With HipYawPitch held at 0 the foot orientation is
// Rx(HipRoll)·Ry(HipPitch + KneePitch + AnklePitch)·Rx(AnkleRoll), so a zero-yaw target is
// reachable only when its pitch is 0 or its hip roll comes out 0 (feet flat on the ground are
// always fine). Throws NaoLegUnreachable if the yaw is not 0 (beyond 1e-9 rad), the ankle is
// farther from the hip than the leg length, the orientation needs hip yaw, or an angle leaves the
// URDF limits (tolerance 1e-9 rad).
NaoLegAngles nao_leg_inverse(LegSide side, const NaoFootPose& target,
                             const NaoLegGeometry& geometry = {});

// A foot pitched about a line across its sole (toe-off, heel strike, a pitched swing foot): the
// line lies at foot-frame x = edge_x_m from the sole point (toe edge +0.10 m, heel edge −0.05 m,
// the sole point itself 0), stays horizontal, and its midpoint is at edge_m (torso frame for
// nao_leg_inverse_edge). The foot is pitched by pitch_rad about it (positive: heel up, toes
// down, as NaoFootPose::pitch_rad).
struct NaoEdgeFoot {
  Eigen::Vector3d edge_m = Eigen::Vector3d::Zero();
  double edge_x_m = 0.0;
  double pitch_rad = 0.0;
};

// Inverse kinematics for a NaoEdgeFoot. A pitched foot with zero yaw would need HipRoll = 0
// (see nao_leg_inverse); here the yaw is left free instead and solved for, so the leg may lean
// sideways: the foot turns by yaw ψ with tan ψ = −sin(pitch)·tan(AnkleRoll) about the vertical
// (up to 0.14 rad on the ground in the 0.2 m steps of a 200 mm/s walk at 2 s per cycle, whose
// edge corners then slide by 6 mm), written to *yaw_rad when given. The forward
// kinematics of the result put the edge midpoint on edge_m with roll 0, pitch pitch_rad and yaw
// ψ. Pitch 0 is exactly nao_leg_inverse of the flat sole at edge_m − (edge_x_m, 0, 0) (yaw 0).
// Throws NaoLegUnreachable like nao_leg_inverse (leg length, URDF limits), or if no yaw solves
// the chain.
NaoLegAngles nao_leg_inverse_edge(LegSide side, const NaoEdgeFoot& target,
                                  const NaoLegGeometry& geometry = {}, double* yaw_rad = nullptr);

}  // namespace motoflex
