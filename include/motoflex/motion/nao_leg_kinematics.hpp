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

  const std::array<std::array<double, 2>, 5>& limits(LegSide side) const {
    return side == LegSide::kLeft ? left_limits_rad : right_limits_rad;
  }
  double leg_length_m() const { return thigh_m + tibia_m; }
  // Hip joint (HipRoll/HipPitch axes' intersection) in the torso frame.
  Eigen::Vector3d hip_in_torso_m(LegSide side) const;
  // The same geometry with the joint limits of the model's actuators ("LHipRoll", ...); throws
  // std::invalid_argument if the model lacks one of the ten leg actuators.
  static NaoLegGeometry with_limits_of(const RobotModel& model);
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

}  // namespace motoflex
