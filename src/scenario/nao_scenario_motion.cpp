#include "nao_scenario_motion.hpp"

#include <cstdio>
#include <memory>
#include <stdexcept>
#include <utility>
#include <vector>

#include "motoflex/motion/nao_kick.hpp"
#include "motoflex/motion/nao_walk.hpp"

namespace motoflex::detail {
namespace {

using DoubleFields = std::vector<std::pair<const char*, double*>>;

void read_doubles(const YamlValue& spec, const DoubleFields& fields) {
  for (const auto& [key, target] : fields) *target = spec.get_double(key, *target);
}

// "left" / "right" → true for left.
bool read_side(const YamlValue& spec, const char* key, bool default_left) {
  const auto field = spec.find(key);
  if (!field) return default_left;
  const std::string side = field->as_string();
  if (side != "left" && side != "right") field->fail("expected 'left' or 'right'");
  return side == "left";
}

// `joint_limits: urdf | stops` (NaoWalkParams::joint_limits).
NaoJointLimits read_joint_limits(const YamlValue& spec, NaoJointLimits fallback) {
  const auto field = spec.find("joint_limits");
  if (!field) return fallback;
  const std::string value = field->as_string();
  if (value == "urdf") return NaoJointLimits::kUrdf;
  if (value == "stops") return NaoJointLimits::kStops;
  field->fail("expected 'urdf' (the URDF's limits) or 'stops' (only those the robot simulates)");
}

// Turns a planner error ("<parameter> = <value>: ...", or anything else) into an InputError at
// the parameter's key when the file sets it, at the motion's mapping otherwise.
[[noreturn]] void fail_at_parameter(const YamlValue& spec, const std::exception& error) {
  const std::string message = error.what();
  const std::size_t end = message.find(" = ");
  if (end != std::string::npos && end < 40) {
    if (const auto field = spec.find(message.substr(0, end))) field->fail(message);
  }
  spec.fail(message);
}

std::string format(const char* pattern, double a, double b) {
  char buffer[160];
  std::snprintf(buffer, sizeof(buffer), pattern, a, b);
  return buffer;
}

NaoScenarioMotion walk_from_yaml(const YamlValue& spec, const RobotModel& model,
                                 const std::map<std::string, double>& walk_options) {
  spec.require_keys_within({"speed_mm_s",       "step_duration_s",
                            "step_height_m",    "double_support_ratio",
                            "com_height_m",     "foot_spacing_m",
                            "start_s",          "stop_s",
                            "duration_s",       "rate_hz",
                            "zmp_offset_x_m",   "zmp_offset_y_m",
                            "zmp_travel_x_m",   "zmp_transfer_smoothing",
                            "toe_off_rad",      "heel_strike_rad",
                            "torso_offset_x_m", "preview_s",
                            "first_swing",      "joint_limits"});
  NaoWalkParams p;
  const DoubleFields fields = p.numeric_fields();
  read_doubles(spec, fields);
  std::string changed;
  for (const auto& [key, value] : walk_options) {
    bool known = false;
    for (const auto& [name, target] : fields) {
      if (key != name) continue;
      *target = value;
      known = true;
    }
    if (!known) spec.fail("walk option '" + key + "' is not a numeric walk key");
    changed += ", " + key + format(" %g", value, 0.0);
  }
  p.first_swing_left = read_side(spec, "first_swing", p.first_swing_left);
  p.joint_limits = read_joint_limits(spec, p.joint_limits);
  try {
    auto plan = std::make_shared<const NaoWalkPlan>(plan_nao_walk(model, p));
    return {
        plan->commands, p.rate_hz,
        format("Nao walk %g mm/s, step duration %g s", p.speed_mm_s, p.step_duration_s) + changed,
        plan};
  } catch (const std::invalid_argument& error) {
    fail_at_parameter(spec, error);
  }
}

NaoScenarioMotion kick_from_yaml(const YamlValue& spec, const RobotModel& model) {
  spec.require_keys_within({"kick_leg", "com_height_m", "foot_spacing_m", "support_com_x_m",
                            "support_com_y_m", "lift_height_m", "swing_inward_m", "backswing_m",
                            "reach_m", "rest_s", "shift_s", "lift_s", "backswing_s", "kick_s",
                            "return_s", "put_down_s", "shift_back_s", "rate_hz"});
  NaoKickParams p;
  read_doubles(spec, {{"com_height_m", &p.com_height_m},
                      {"foot_spacing_m", &p.foot_spacing_m},
                      {"support_com_x_m", &p.support_com_x_m},
                      {"support_com_y_m", &p.support_com_y_m},
                      {"lift_height_m", &p.lift_height_m},
                      {"swing_inward_m", &p.swing_inward_m},
                      {"backswing_m", &p.backswing_m},
                      {"reach_m", &p.reach_m},
                      {"rest_s", &p.rest_s},
                      {"shift_s", &p.shift_s},
                      {"lift_s", &p.lift_s},
                      {"backswing_s", &p.backswing_s},
                      {"kick_s", &p.kick_s},
                      {"return_s", &p.return_s},
                      {"put_down_s", &p.put_down_s},
                      {"shift_back_s", &p.shift_back_s},
                      {"rate_hz", &p.rate_hz}});
  p.kick_left = read_side(spec, "kick_leg", p.kick_left);
  try {
    return {nao_kick_trajectory(model, p), p.rate_hz,
            std::string("Nao kick, ") + (p.kick_left ? "left" : "right") +
                format(" leg, %g s", p.duration_s(), 0.0),
            nullptr};
  } catch (const std::invalid_argument& error) {
    fail_at_parameter(spec, error);
  }
}

}  // namespace

std::optional<NaoScenarioMotion> nao_motion_from_yaml(
    const YamlValue& motion, const RobotModel& model,
    const std::map<std::string, double>& walk_options) {
  if (const auto walk = motion.find("walk")) return walk_from_yaml(*walk, model, walk_options);
  if (const auto kick = motion.find("kick")) return kick_from_yaml(*kick, model);
  return std::nullopt;
}

}  // namespace motoflex::detail
