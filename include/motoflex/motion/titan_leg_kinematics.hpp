#pragma once

#include <Eigen/Core>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// The four legs of TITAN-VIII (seed 000, Fig. 3): front-left, front-right, hind-left,
// hind-right. Joint names are "<leg>_J1" … "<leg>_J4".
enum class TitanLeg { kFL = 0, kFR = 1, kHL = 2, kHR = 3 };
inline constexpr std::array<TitanLeg, 4> kTitanLegs = {TitanLeg::kFL, TitanLeg::kFR, TitanLeg::kHL,
                                                       TitanLeg::kHR};
const char* to_string(TitanLeg leg);

// Joint angles of one leg in the model's sign conventions (scenarios/robots/titan8/README.md):
// J1 hip yaw, J2 thigh (positive lifts the knee), J3 relative knee (positive swings the shank's
// lower end outward), J4 ankle (sole parallel to the body when J4 = −(J2 + J3)).
struct TitanLegAngles {
  double j1_rad = 0.0;
  double j2_rad = 0.0;
  double j3_rad = 0.0;
  double j4_rad = 0.0;
};

// Points of one leg in the body frame (x forward, y left, z up, origin at the body centre in the
// plane of the hip joints), from forward kinematics.
struct TitanLegPoints {
  Eigen::Vector3d hip_m;    // J1 axis point (on the body)
  Eigen::Vector3d thigh_m;  // J2 axis point
  Eigen::Vector3d knee_m;   // J3 axis point
  Eigen::Vector3d ankle_m;  // J4 axis point
  Eigen::Vector3d sole_m;   // centre of the sole: foot_height_m below the ankle along the foot
};

// Dimensions of one serial-link leg (paper Fig. 2c), read from the loaded robot model so that
// the kinematics and the simulated bodies cannot disagree.
struct TitanLegGeometry {
  TitanLeg leg = TitanLeg::kFL;
  Eigen::Vector3d hip_m = Eigen::Vector3d::Zero();  // J1 axis point, body frame
  double zero_heading_rad = 0.0;      // direction of the leg at J1 = 0, about +z from +x
  double hip_link_m = 0.0;            // L0: J1 → J2, horizontal
  double thigh_m = 0.0;               // L1: J2 → J3 (horizontal at J2 = 0)
  double shank_m = 0.0;               // L2: J3 → J4 (vertical at J2 = J3 = 0)
  double foot_height_m = 0.0;         // J4 → sole
  std::array<double, 4> lower_rad{};  // URDF limits of J1 … J4
  std::array<double, 4> upper_rad{};
};

// Thrown by the inverse kinematics for a sole position the leg cannot reach with the sole
// parallel to the body, or reaches only beyond a joint limit. The message names the leg, the
// target and the reason.
class TitanUnreachable : public std::domain_error {
 public:
  using std::domain_error::domain_error;
};

// Forward kinematics of one leg: every joint point and the sole centre, body frame [m].
TitanLegPoints titan_leg_points(const TitanLegGeometry& geometry, const TitanLegAngles& angles);

// Analytic inverse kinematics: the joint angles that put the sole centre at `sole_m` (body
// frame) with the sole parallel to the body (J4 = −(J2 + J3)), on the knee-up branch (the knee
// above the line from J2 to the ankle, as in the standard posture). Throws TitanUnreachable when
// the ankle is farther from J2 than thigh + shank, closer than |thigh − shank|, on the J1 axis,
// or when an angle falls outside the joint limits.
TitanLegAngles titan_leg_ik(const TitanLegGeometry& geometry, const Eigen::Vector3d& sole_m);

// Distance from J2 to the ankle over thigh + shank for a sole target (1 = leg fully stretched);
// a measure of how much reach is left. Does not throw.
double titan_leg_reach_fraction(const TitanLegGeometry& geometry, const Eigen::Vector3d& sole_m);

// The four legs of a loaded TITAN-VIII model together with where their joints sit in the model's
// actuator order.
class TitanKinematics {
 public:
  // Reads hip points, link lengths, foot height and joint limits from the model's joints and
  // foot boxes (build configuration = body frame). Throws std::invalid_argument naming the joint
  // when the model is not a TITAN-VIII-like leg layout: a missing or unactuated <leg>_J1…J4, a
  // J1 axis that is not +z, a J2–J4 axis not perpendicular to the leg's vertical plane in the
  // direction that makes positive J2 lift the knee, a thigh that is not horizontal or a shank
  // that is not vertical at the zero pose, or a foot without a box.
  explicit TitanKinematics(const RobotModel& model);

  const TitanLegGeometry& geometry(TitanLeg leg) const {
    return legs_[static_cast<std::size_t>(leg)];
  }
  // Model actuator indices of J1 … J4 of a leg.
  const std::array<std::size_t, 4>& actuators(TitanLeg leg) const {
    return actuators_[static_cast<std::size_t>(leg)];
  }
  std::size_t actuator_count() const { return stand_pose_rad_.size(); }

  // Joint angles of one leg read from a full pose in model actuator order.
  TitanLegAngles leg_angles(TitanLeg leg, const std::vector<double>& pose_rad) const;

  // Full pose in model actuator order with every sole at its target (index = TitanLeg) and the
  // soles parallel to the body; joints of no leg keep their stand-pose angle. Throws
  // TitanUnreachable like titan_leg_ik.
  std::vector<double> pose_rad(const std::array<Eigen::Vector3d, 4>& sole_m) const;

  // Sole centres (body frame) of all four legs for a full pose in model actuator order.
  std::array<Eigen::Vector3d, 4> sole_positions_m(const std::vector<double>& pose_rad) const;

 private:
  std::array<TitanLegGeometry, 4> legs_;
  std::array<std::array<std::size_t, 4>, 4> actuators_{};
  std::vector<double> stand_pose_rad_;
};

}  // namespace motoflex
