#include "motoflex/robot_setup/urdf_hints.hpp"

#include <cmath>

#include "motoflex/core/number_text.hpp"

namespace motoflex {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

}  // namespace

ScreenedJoint screen_urdf_joint(const UrdfJoint& joint) {
  ScreenedJoint out;
  const bool prismatic = joint.type == UrdfJointType::kPrismatic;
  const std::string effort_unit = prismatic ? " N" : " N·m";
  const std::string speed_unit = prismatic ? " m/s" : " rad/s";
  const auto set_aside = [&](const std::string& what, double value, const std::string& unit,
                             double threshold) {
    out.assumptions.push_back({joint.name + " " + what, "unknown (law default)",
                               "URDF " + what + " " + short_number_text(value) + unit +
                                   " looks like a placeholder (>= " + short_number_text(threshold) +
                                   unit + ")"});
    return kNaN;
  };
  const double effort_limit = prismatic ? kPlaceholderForce_n : kPlaceholderEffort_nm;
  out.hints.effort = joint.effort >= effort_limit
                         ? set_aside("effort", joint.effort, effort_unit, effort_limit)
                         : joint.effort;
  const double speed_limit = prismatic ? kPlaceholderSpeed_m_s : kPlaceholderSpeed_rad_s;
  out.hints.velocity = joint.velocity >= speed_limit
                           ? set_aside("velocity", joint.velocity, speed_unit, speed_limit)
                           : joint.velocity;
  out.hints.damping = joint.damping >= 0.0 ? joint.damping : kNaN;
  out.hints.friction = joint.friction >= 0.0 ? joint.friction : kNaN;
  if (joint.limited) {
    const double threshold = prismatic ? kPlaceholderTravel_m : kPlaceholderAngle_rad;
    if (std::abs(joint.lower_rad) >= threshold || std::abs(joint.upper_rad) >= threshold) {
      const double range = prismatic ? kDefaultTravel_m : kDefaultRange_rad;
      out.limits = std::pair{-range, range};
      const std::string unit = prismatic ? " m" : " rad";
      out.assumptions.push_back(
          {joint.name + " limits",
           "[" + short_number_text(-range) + ", " + short_number_text(range) + "]" + unit,
           "URDF limits [" + short_number_text(joint.lower_rad) + ", " +
               short_number_text(joint.upper_rad) + "]" + unit +
               " look like placeholders (|limit| >= " + short_number_text(threshold) + unit + ")"});
    }
  }
  return out;
}

}  // namespace motoflex
