#include "motoflex/motion/nao_leg_kinematics.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include "motoflex/model/body_kinematics.hpp"

namespace motoflex {
namespace {

constexpr double kLimitTolerance_rad = 1e-9;
// |M(0,1)| above this means the orientation needs a rotation the chain cannot make (see below).
constexpr double kYawCouplingTolerance = 1e-9;

Eigen::Matrix3d rot_x(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitX()).matrix();
}
Eigen::Matrix3d rot_y(double a) {
  return Eigen::AngleAxisd(a, Eigen::Vector3d::UnitY()).matrix();
}

std::string format(const char* pattern, double a, double b = 0.0, double c = 0.0) {
  char buffer[256];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b, c);
  return buffer;
}

std::string joint_name(LegSide side, int joint) {
  return std::string(side == LegSide::kLeft ? "L" : "R") + nao_leg::kJointNames[joint];
}

}  // namespace

const char* to_string(LegSide side) {
  return side == LegSide::kLeft ? "left" : "right";
}

Eigen::Vector3d NaoLegGeometry::hip_in_torso_m(LegSide side) const {
  return {0.0, side == LegSide::kLeft ? hip_offset_y_m : -hip_offset_y_m, -hip_offset_z_m};
}

NaoLegGeometry NaoLegGeometry::with_limits_of(const RobotModel& model) {
  NaoLegGeometry geometry;
  for (const LegSide side : {LegSide::kLeft, LegSide::kRight}) {
    auto& limits = side == LegSide::kLeft ? geometry.left_limits_rad : geometry.right_limits_rad;
    for (int j = 0; j < 5; ++j) {
      const std::string name = joint_name(side, j);
      const auto index = model.actuator_index(name);
      if (!index) {
        throw std::invalid_argument("robot '" + model.name + "' has no actuated joint " + name +
                                    " (a Nao leg needs all five per side)");
      }
      limits[j] = {model.actuators[*index].lower_rad, model.actuators[*index].upper_rad};
    }
  }
  return geometry;
}

NaoLegGeometry NaoLegGeometry::of(const RobotModel& model, NaoJointLimits limits) {
  NaoLegGeometry geometry = with_limits_of(model);
  geometry.limits_without_stops = limits == NaoJointLimits::kUrdf && !model.joint_stops;
  if (limits == NaoJointLimits::kStops && !model.joint_stops) {
    constexpr double kInf = std::numeric_limits<double>::infinity();
    for (auto* side_limits : {&geometry.left_limits_rad, &geometry.right_limits_rad}) {
      for (auto& joint : *side_limits) joint = {-kInf, kInf};
    }
  }
  const auto anchor = [&model](const char* name) {
    const ActuatorSpec& actuator = model.actuators[*model.actuator_index(name)];
    return model.joints[actuator.joint].anchor_W0_m;
  };
  const auto nanometres = [](double length_m) { return std::round(length_m * 1e9) / 1e9; };
  geometry.hip_offset_y_m = nanometres(0.5 * (anchor("LHipRoll") - anchor("RHipRoll")).norm());
  geometry.thigh_m = nanometres((anchor("LKneePitch") - anchor("LHipRoll")).norm());
  geometry.tibia_m = nanometres((anchor("LAnklePitch") - anchor("LKneePitch")).norm());
  const double sole_z =
      lowest_foot_point_z(model, body_poses(model, std::vector<double>(model.actuators.size())));
  if (std::isfinite(sole_z)) {
    geometry.foot_height_m = nanometres(anchor("LAnkleRoll").z() - sole_z);
  }
  return geometry;
}

NaoFootPose nao_leg_forward(LegSide side, const NaoLegAngles& q, const NaoLegGeometry& g) {
  using namespace nao_leg;
  const Eigen::Matrix3d R_hip = rot_x(q[kHipRoll]) * rot_y(q[kHipPitch]);
  const Eigen::Matrix3d R_tibia = R_hip * rot_y(q[kKneePitch]);
  const Eigen::Matrix3d R_foot = R_tibia * rot_y(q[kAnklePitch]) * rot_x(q[kAnkleRoll]);
  const Eigen::Vector3d ankle = g.hip_in_torso_m(side) + R_hip * Eigen::Vector3d(0, 0, -g.thigh_m) +
                                R_tibia * Eigen::Vector3d(0, 0, -g.tibia_m);
  NaoFootPose pose;
  pose.position_m = ankle + R_foot * Eigen::Vector3d(0, 0, -g.foot_height_m);
  // Z-Y-X angles of R_foot.
  pose.yaw_rad = std::atan2(R_foot(1, 0), R_foot(0, 0));
  pose.pitch_rad = std::asin(std::clamp(-R_foot(2, 0), -1.0, 1.0));
  pose.roll_rad = std::atan2(R_foot(2, 1), R_foot(2, 2));
  return pose;
}

namespace {

// The chain for a sole point at `sole` (torso frame) with orientation R_foot: the five angles
// when the orientation is one the chain can make, and the yaw coupling M(0,1) that must be 0
// for it (see below). Throws NaoLegUnreachable when the ankle is beyond the leg length.
NaoLegAngles solve_chain(const std::string& leg, const Eigen::Vector3d& hip,
                         const Eigen::Vector3d& sole, const Eigen::Matrix3d& R_foot,
                         const NaoLegGeometry& g, double& yaw_coupling) {
  using namespace nao_leg;
  const Eigen::Vector3d ankle = sole + R_foot * Eigen::Vector3d(0, 0, g.foot_height_m);
  // Hip seen from the ankle in the foot frame: v = Rx(−ar)·Ry(−ap)·w with
  // w = (−L1·sin kp, 0, L2 + L1·cos kp), so ar, kp and ap follow from v alone.
  const Eigen::Vector3d v = R_foot.transpose() * (hip - ankle);
  const double L1 = g.thigh_m, L2 = g.tibia_m;
  const double d = v.norm();
  if (d > L1 + L2 + 1e-12) {
    throw NaoLegUnreachable(leg + format("hip-to-ankle distance %.4f m exceeds the leg length "
                                         "%.4f m (thigh + tibia)",
                                         d, L1 + L2));
  }
  NaoLegAngles q{};
  // v_y = sin(ar)·u_z, v_z = cos(ar)·u_z: the ankle roll limits lie within ±π/2, so take the
  // solution there (u_z < 0, the hip "below" the ankle in the foot frame, flips it by π).
  q[kAnkleRoll] = std::atan2(v.y(), v.z());
  if (q[kAnkleRoll] > 0.5 * std::numbers::pi) q[kAnkleRoll] -= std::numbers::pi;
  if (q[kAnkleRoll] < -0.5 * std::numbers::pi) q[kAnkleRoll] += std::numbers::pi;
  const double cos_knee = std::clamp((d * d - L1 * L1 - L2 * L2) / (2.0 * L1 * L2), -1.0, 1.0);
  q[kKneePitch] = std::acos(cos_knee);
  const Eigen::Vector3d u = rot_x(q[kAnkleRoll]) * v;  // in the x-z plane of the ankle
  const double wx = -L1 * std::sin(q[kKneePitch]);
  const double wz = L2 + L1 * std::cos(q[kKneePitch]);
  q[kAnklePitch] = std::atan2(wx, wz) - std::atan2(u.x(), u.z());
  // What is left for the hip: Rx(hr)·Ry(θ) = R_foot·Rx(−ar), θ = hp + kp + ap. A matrix of that
  // form has M(0,1) = 0; otherwise the orientation would need HipYawPitch.
  const Eigen::Matrix3d M = R_foot * rot_x(-q[kAnkleRoll]);
  yaw_coupling = M(0, 1);
  q[kHipRoll] = std::atan2(M(2, 1), M(1, 1));
  const double theta = std::atan2(M(0, 2), M(0, 0));
  q[kHipPitch] = theta - q[kKneePitch] - q[kAnklePitch];
  // Bring the hip pitch into (−π, π].
  q[kHipPitch] = std::remainder(q[kHipPitch], 2.0 * std::numbers::pi);
  return q;
}

void check_limits(LegSide side, const std::string& leg, const NaoLegAngles& q,
                  const NaoLegGeometry& g) {
  const auto& limits = g.limits(side);
  for (int j = 0; j < 5; ++j) {
    if (q[j] < limits[j][0] - kLimitTolerance_rad || q[j] > limits[j][1] + kLimitTolerance_rad) {
      throw NaoLegUnreachable(
          leg + joint_name(side, j) +
          format(" = %.4f rad is outside its URDF limits [%.4f, %.4f]", q[j], limits[j][0],
                 limits[j][1]) +
          (g.limits_without_stops
               ? " (the robot has no joint stops: joint_limits: stops plans without them)"
               : ""));
    }
  }
}

}  // namespace

NaoLegAngles nao_leg_inverse(LegSide side, const NaoFootPose& target, const NaoLegGeometry& g) {
  const std::string leg = std::string(to_string(side)) + " leg: ";
  if (std::abs(target.yaw_rad) > kYawCouplingTolerance) {
    throw NaoLegUnreachable(leg + format("foot yaw %.4g rad is not reachable: HipYawPitch is held "
                                         "at 0, so the yaw must be 0",
                                         target.yaw_rad));
  }
  const Eigen::Matrix3d R_foot = rot_y(target.pitch_rad) * rot_x(target.roll_rad);
  double coupling = 0.0;
  const NaoLegAngles q =
      solve_chain(leg, g.hip_in_torso_m(side), target.position_m, R_foot, g, coupling);
  if (std::abs(coupling) > kYawCouplingTolerance) {
    throw NaoLegUnreachable(
        leg + format("foot roll %.4g rad with pitch %.4g rad is not reachable at this position: "
                     "with HipYawPitch held at 0 a pitched foot needs hip roll 0 (it would be "
                     "%.4g rad)",
                     target.roll_rad, target.pitch_rad, q[nao_leg::kHipRoll]));
  }
  check_limits(side, leg, q, g);
  return q;
}

NaoLegAngles nao_leg_inverse_edge(LegSide side, const NaoEdgeFoot& target, const NaoLegGeometry& g,
                                  double* yaw_rad) {
  if (yaw_rad != nullptr) *yaw_rad = 0.0;
  if (target.pitch_rad == 0.0) {
    NaoFootPose flat;
    flat.position_m = target.edge_m - Eigen::Vector3d(target.edge_x_m, 0.0, 0.0);
    return nao_leg_inverse(side, flat, g);
  }
  const std::string leg = std::string(to_string(side)) + " leg: ";
  const Eigen::Vector3d hip = g.hip_in_torso_m(side);
  const Eigen::Vector3d edge_in_foot(target.edge_x_m, 0.0, 0.0);
  // With R = Rz(ψ)·Ry(θ) the coupling M(0,1) = −sin ψ·cos ar − cos ψ·sin θ·sin ar vanishes for
  // tan ψ = −sin θ·tan ar; ar itself depends only weakly on ψ (through the sole position), so
  // the fixed-point iteration contracts by about sin θ·|edge_x|/leg per step.
  double yaw = 0.0;
  NaoLegAngles q{};
  for (int iteration = 0; iteration < 100; ++iteration) {
    const Eigen::Matrix3d R_foot =
        Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).matrix() * rot_y(target.pitch_rad);
    double coupling = 0.0;
    q = solve_chain(leg, hip, target.edge_m - R_foot * edge_in_foot, R_foot, g, coupling);
    if (std::abs(coupling) <= 1e-13) {
      check_limits(side, leg, q, g);
      if (yaw_rad != nullptr) *yaw_rad = yaw;
      return q;
    }
    yaw = std::atan(-std::sin(target.pitch_rad) * std::tan(q[nao_leg::kAnkleRoll]));
  }
  throw NaoLegUnreachable(leg + format("no foot yaw solves the leg for pitch %.4g rad about the "
                                       "edge at x = %.4g m",
                                       target.pitch_rad, target.edge_x_m));
}

}  // namespace motoflex
