#pragma once

// What a URDF's joint limits say, screened for placeholders. CAD exporters and hand-written
// URDFs fill fields they do not know with round numbers (effort 0 or 1000, velocity 100, limits
// ±10 rad); starting values and search bounds derived from them would be absurd. A value at or
// beyond these thresholds is treated as unknown and replaced by a documented default.

#include <numbers>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/model/urdf_tree.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"

namespace motoflex {

inline constexpr double kPlaceholderEffort_nm = 1000.0;   // revolute effort >= this
inline constexpr double kPlaceholderForce_n = 10000.0;    // prismatic effort >= this
inline constexpr double kPlaceholderSpeed_rad_s = 100.0;  // revolute velocity >= this
inline constexpr double kPlaceholderSpeed_m_s = 10.0;     // prismatic velocity >= this
// A revolute limit of a full turn or more either way (|limit| >= 2π, within 0.01 rad) or a
// prismatic one of 10 m or more stands for "no limit given".
inline constexpr double kPlaceholderAngle_rad = 2.0 * std::numbers::pi - 0.01;
inline constexpr double kPlaceholderTravel_m = 10.0;
// What replaces placeholder limits: half a turn either way, or ±0.1 m.
inline constexpr double kDefaultRange_rad = std::numbers::pi;
inline constexpr double kDefaultTravel_m = 0.1;

// One assumption made on the user's behalf: what, the choice, and why.
struct Assumption {
  std::string subject;
  std::string choice;
  std::string reason;
};

struct ScreenedJoint {
  JointHints hints;                                 // NaN where the URDF says nothing usable
  std::optional<std::pair<double, double>> limits;  // replacement for placeholder limits
  std::vector<Assumption> assumptions;              // one per value set aside
};

// Screens one movable joint's <limit> and <dynamics>: efforts and speeds that are absent, zero
// or placeholders become NaN, placeholder limits are replaced by ±kDefaultRange_rad (±
// kDefaultTravel_m), negative damping or friction is dropped.
ScreenedJoint screen_urdf_joint(const UrdfJoint& joint);

}  // namespace motoflex
