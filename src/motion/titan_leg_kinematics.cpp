#include "motoflex/motion/titan_leg_kinematics.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace motoflex {
namespace {

// Geometry read from a URDF is exact to the printed digits; anything beyond this is a layout
// the leg model does not describe.
constexpr double kLayoutTolerance_m = 1e-9;
constexpr double kAxisTolerance = 1e-9;

const char* const kJointSuffix[4] = {"_J1", "_J2", "_J3", "_J4"};

double wrap_angle(double a) {
  a = std::fmod(a + std::numbers::pi, 2.0 * std::numbers::pi);
  if (a < 0.0) a += 2.0 * std::numbers::pi;
  return a - std::numbers::pi;
}

// Unit vector of the leg's vertical plane (outward, horizontal) for a heading about +z.
Eigen::Vector3d outward(double heading_rad) {
  return {std::cos(heading_rad), std::sin(heading_rad), 0.0};
}

std::string describe(TitanLeg leg, const Eigen::Vector3d& p) {
  std::ostringstream out;
  out << to_string(leg) << " sole target (" << p.x() << ", " << p.y() << ", " << p.z() << ") m";
  return out.str();
}

[[noreturn]] void layout_error(const std::string& joint, const std::string& what) {
  throw std::invalid_argument("TITAN-VIII kinematics: " + joint + ": " + what);
}

}  // namespace

const char* to_string(TitanLeg leg) {
  switch (leg) {
    case TitanLeg::kFL:
      return "FL";
    case TitanLeg::kFR:
      return "FR";
    case TitanLeg::kHL:
      return "HL";
    case TitanLeg::kHR:
      return "HR";
  }
  return "?";
}

TitanLegPoints titan_leg_points(const TitanLegGeometry& g, const TitanLegAngles& q) {
  // In the leg's vertical plane, r outward from the J1 axis and z up. J2, J3 and J4 rotate
  // about u × z, which turns u towards +z (README sign conventions).
  const Eigen::Vector3d u = outward(g.zero_heading_rad + q.j1_rad);
  const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
  const double shank_rad = q.j2_rad + q.j3_rad;  // shank from the vertical, outward positive
  const double foot_rad = shank_rad + q.j4_rad;  // foot from the vertical
  TitanLegPoints p;
  p.hip_m = g.hip_m;
  p.thigh_m = p.hip_m + g.hip_link_m * u;
  p.knee_m = p.thigh_m + g.thigh_m * (std::cos(q.j2_rad) * u + std::sin(q.j2_rad) * z);
  p.ankle_m = p.knee_m + g.shank_m * (std::sin(shank_rad) * u - std::cos(shank_rad) * z);
  p.sole_m = p.ankle_m + g.foot_height_m * (std::sin(foot_rad) * u - std::cos(foot_rad) * z);
  return p;
}

double titan_leg_reach_fraction(const TitanLegGeometry& g, const Eigen::Vector3d& sole_m) {
  const Eigen::Vector3d ankle = sole_m + g.foot_height_m * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d d = ankle - g.hip_m;
  const double r = std::hypot(d.x(), d.y()) - g.hip_link_m;
  return std::hypot(r, d.z()) / (g.thigh_m + g.shank_m);
}

TitanLegAngles titan_leg_ik(const TitanLegGeometry& g, const Eigen::Vector3d& sole_m) {
  if (!sole_m.allFinite()) throw TitanUnreachable(describe(g.leg, sole_m) + " is not finite");
  // Sole parallel to the body: the ankle is straight above the sole centre.
  const Eigen::Vector3d ankle = sole_m + g.foot_height_m * Eigen::Vector3d::UnitZ();
  const Eigen::Vector3d d = ankle - g.hip_m;
  const double radius = std::hypot(d.x(), d.y());
  if (radius < 1e-6) {
    throw TitanUnreachable(describe(g.leg, sole_m) + ": the ankle would sit on the J1 axis");
  }
  TitanLegAngles q;
  q.j1_rad = wrap_angle(std::atan2(d.y(), d.x()) - g.zero_heading_rad);

  // Planar two-link problem J2 → J3 → J4 in the leg plane (r outward from J2, z up).
  const double r = radius - g.hip_link_m;
  const double z = d.z();
  const double reach = std::hypot(r, z);
  const double l1 = g.thigh_m, l2 = g.shank_m;
  if (reach > l1 + l2 || reach < std::abs(l1 - l2)) {
    std::ostringstream out;
    out << describe(g.leg, sole_m) << " is out of reach: J2 to ankle " << reach
        << " m, the leg spans " << std::abs(l1 - l2) << " … " << l1 + l2 << " m";
    throw TitanUnreachable(out.str());
  }
  const double line_rad = std::atan2(z, r);
  const double cos_inner = (l1 * l1 + reach * reach - l2 * l2) / (2.0 * l1 * reach);
  const double inner_rad = std::acos(std::clamp(cos_inner, -1.0, 1.0));
  q.j2_rad = line_rad + inner_rad;  // knee-up branch
  const double knee_r = l1 * std::cos(q.j2_rad);
  const double knee_z = l1 * std::sin(q.j2_rad);
  const double shank_rad = std::atan2(r - knee_r, knee_z - z);
  q.j3_rad = shank_rad - q.j2_rad;
  q.j4_rad = -shank_rad;  // J4 = −(J2 + J3): sole parallel

  const std::array<double, 4> angles = {q.j1_rad, q.j2_rad, q.j3_rad, q.j4_rad};
  for (std::size_t i = 0; i < 4; ++i) {
    if (angles[i] < g.lower_rad[i] || angles[i] > g.upper_rad[i]) {
      std::ostringstream out;
      out << describe(g.leg, sole_m) << " needs J" << i + 1 << " = " << angles[i]
          << " rad, outside the joint limits [" << g.lower_rad[i] << ", " << g.upper_rad[i] << "]";
      throw TitanUnreachable(out.str());
    }
  }
  return q;
}

TitanKinematics::TitanKinematics(const RobotModel& model)
    : stand_pose_rad_(model.stand_pose_vector()) {
  // The model's build configuration (all joints at 0) is expressed in the root link's frame,
  // which is the body frame of the kinematics.
  for (const TitanLeg leg : kTitanLegs) {
    const auto l = static_cast<std::size_t>(leg);
    std::array<const JointSpec*, 4> joint{};
    for (std::size_t i = 0; i < 4; ++i) {
      const std::string name = std::string(to_string(leg)) + kJointSuffix[i];
      const auto index = model.actuator_index(name);
      if (!index) layout_error(name, "not an actuated joint of " + model.name);
      const ActuatorSpec& actuator = model.actuators[*index];
      joint[i] = &model.joints[actuator.joint];
      if (joint[i]->kind != JointKind::kHinge) layout_error(name, "must be a plain hinge");
      actuators_[l][i] = *index;
    }
    TitanLegGeometry& g = legs_[l];
    g.leg = leg;
    for (std::size_t i = 0; i < 4; ++i) {
      g.lower_rad[i] = joint[i]->lower1_rad;
      g.upper_rad[i] = joint[i]->upper1_rad;
    }
    const std::string leg_name = to_string(leg);
    g.hip_m = joint[0]->anchor_W0_m;
    if ((joint[0]->axis1_W0 - Eigen::Vector3d::UnitZ()).norm() > kAxisTolerance) {
      layout_error(leg_name + "_J1", "axis must be +z");
    }
    const Eigen::Vector3d hip_link = joint[1]->anchor_W0_m - g.hip_m;
    if (std::abs(hip_link.z()) > kLayoutTolerance_m || hip_link.norm() < 1e-6) {
      layout_error(leg_name + "_J2", "must sit a horizontal hip link away from J1");
    }
    g.hip_link_m = hip_link.norm();
    g.zero_heading_rad = std::atan2(hip_link.y(), hip_link.x());
    const Eigen::Vector3d u = outward(g.zero_heading_rad);
    const Eigen::Vector3d bend_axis = u.cross(Eigen::Vector3d::UnitZ());
    for (std::size_t i = 1; i < 4; ++i) {
      if ((joint[i]->axis1_W0 - bend_axis).norm() > kAxisTolerance) {
        layout_error(leg_name + kJointSuffix[i],
                     "axis must be horizontal, perpendicular to the leg, with positive J2 "
                     "lifting the knee");
      }
    }
    const Eigen::Vector3d thigh = joint[2]->anchor_W0_m - joint[1]->anchor_W0_m;
    g.thigh_m = thigh.dot(u);
    if ((thigh - g.thigh_m * u).norm() > kLayoutTolerance_m || g.thigh_m <= 0.0) {
      layout_error(leg_name + "_J3", "the thigh must point straight outward at the zero pose");
    }
    const Eigen::Vector3d shank = joint[3]->anchor_W0_m - joint[2]->anchor_W0_m;
    g.shank_m = -shank.z();
    if (std::hypot(shank.x(), shank.y()) > kLayoutTolerance_m || g.shank_m <= 0.0) {
      layout_error(leg_name + "_J4", "the shank must hang straight down at the zero pose");
    }
    // The sole is the bottom face of the foot's contact box, centred under the ankle.
    const BodySpec& foot = model.bodies[joint[3]->child_body];
    const CollisionShape* sole_box = nullptr;
    for (const CollisionShape& box : foot.collisions) {
      if (box.is_foot && box.kind == ShapeKind::kBox) sole_box = &box;
    }
    if (sole_box == nullptr) layout_error(leg_name + "_J4", "its child body has no foot box");
    const Eigen::Vector3d box_centre = foot.com_W0_m + sole_box->X_BG.translation();
    const Eigen::Vector3d bottom =
        box_centre - 0.5 * sole_box->size_m.z() * sole_box->X_BG.linear().col(2);
    if ((sole_box->X_BG.linear() - Eigen::Matrix3d::Identity()).norm() > kAxisTolerance ||
        (bottom - joint[3]->anchor_W0_m).head<2>().norm() > kLayoutTolerance_m) {
      layout_error(leg_name + "_J4", "the foot box must be level and centred under the ankle");
    }
    g.foot_height_m = joint[3]->anchor_W0_m.z() - bottom.z();
  }
}

TitanLegAngles TitanKinematics::leg_angles(TitanLeg leg, const std::vector<double>& pose) const {
  const auto& a = actuators(leg);
  return {pose.at(a[0]), pose.at(a[1]), pose.at(a[2]), pose.at(a[3])};
}

std::vector<double> TitanKinematics::pose_rad(const std::array<Eigen::Vector3d, 4>& sole_m) const {
  std::vector<double> pose = stand_pose_rad_;
  for (const TitanLeg leg : kTitanLegs) {
    const auto l = static_cast<std::size_t>(leg);
    const TitanLegAngles q = titan_leg_ik(legs_[l], sole_m[l]);
    pose[actuators_[l][0]] = q.j1_rad;
    pose[actuators_[l][1]] = q.j2_rad;
    pose[actuators_[l][2]] = q.j3_rad;
    pose[actuators_[l][3]] = q.j4_rad;
  }
  return pose;
}

std::array<Eigen::Vector3d, 4> TitanKinematics::sole_positions_m(
    const std::vector<double>& pose) const {
  std::array<Eigen::Vector3d, 4> out;
  for (const TitanLeg leg : kTitanLegs) {
    const auto l = static_cast<std::size_t>(leg);
    out[l] = titan_leg_points(legs_[l], leg_angles(leg, pose)).sole_m;
  }
  return out;
}

}  // namespace motoflex
