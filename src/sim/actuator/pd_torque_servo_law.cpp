// `servo: pd_torque` — a torque-controlled actuator with a PD position loop (Isaac Lab's ideal
// PD / DC motor actuators, MuJoCo's position actuator with a force limit):
//   τ = clip(kp·(θ_d − θ) − kd·θ̇, limits(θ̇))
// with ±τ_max, and with a no-load speed ω₀ > 0 the motor's linear torque–speed curve
// (clip_torque_speed_nm). Joint friction from BAM's family on τ, armature as joint inertia.
// The kp term is explicit (stable while kp·h²/(I + J) is small; the rollout ends a diverging
// candidate as a model failure); the kd term acts through the rollout's implicit damping row at
// the end-of-step rate, stable for any kd·h/(I + J) (explicitly it diverged beyond 2: a stiff
// leg gain on a light shank swinging in the air).

#include <cmath>
#include <cstdio>
#include <iterator>
#include <string>

#include "motoflex/core/error.hpp"
#include "motoflex/sim/actuator/friction_family.hpp"
#include "motoflex/sim/actuator/servo_stages.hpp"
#include "motoflex/sim/actuator/stance_gains.hpp"

namespace motoflex {
namespace {

struct PdTorqueParams {
  double kp_nm_per_rad = 0.0;
  double kd_nm_s_per_rad = 0.0;
  double torque_max_nm = 0.0;
  double no_load_speed_rad_s = 0.0;  // 0 = no torque–speed curve
};

class PdTorqueServoLaw final : public ServoLaw {
 public:
  PdTorqueServoLaw(PdTorqueParams params, FrictionParams friction, double armature_kg_m2)
      : params_(params),
        friction_(friction),
        armature_kg_m2_(armature_kg_m2),
        external_(friction_reads_external_torque(friction)) {}

  ServoOutput step(const ServoInput& in) override {
    const double pd_nm = params_.kp_nm_per_rad * (in.command_rad - in.angle_rad) -
                         params_.kd_nm_s_per_rad * in.rate_rad_s;
    ServoOutput out;
    out.torque_nm = clip_torque_speed_nm(pd_nm, in.rate_rad_s, params_.torque_max_nm,
                                         params_.no_load_speed_rad_s);
    out.row = joint_friction(friction_, in.rate_rad_s, out.torque_nm, in.external_torque_nm);
    // −kd·θ̇ at the end-of-step rate through the damping row: the offset cancels the start-of-step
    // term inside torque_nm (when the torque is clipped, the row's change over the step is left).
    out.damping_offset_nm = params_.kd_nm_s_per_rad * in.rate_rad_s;
    return out;
  }
  double damping_row_nm_s_per_rad() const override { return params_.kd_nm_s_per_rad; }
  double armature() const override { return armature_kg_m2_; }
  bool needs_external_torque() const override { return external_; }

 private:
  PdTorqueParams params_;
  FrictionParams friction_;
  double armature_kg_m2_;
  bool external_;
};

std::string short_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.4g", value);
  return text;
}

const char* const kLeaves[] = {"kp_nm_per_rad", "kd_nm_s_per_rad", "torque_max_nm",
                               "no_load_speed_rad_s"};

std::vector<std::string> names(const RobotModel& model, std::size_t actuator) {
  return scoped_law_parameter_names(model.actuators[actuator],
                                    {std::begin(kLeaves), std::end(kLeaves)});
}

std::vector<ParameterSpec> defaults(const RobotModel& model, std::size_t actuator) {
  // Generic hobby-to-small-robot values: a stiff but not explicit-unstable loop on ~0.01 kg·m².
  const std::string prefix = servo_parameter_prefix(model.actuators[actuator]);
  const auto spec = [&](const char* leaf, double value, double lower, double upper) {
    const std::string name = prefix + leaf;
    return ParameterSpec{name, unit_from_parameter_name(name), value, lower, upper};
  };
  return {spec("kp_nm_per_rad", 20.0, 0.0, 2000.0), spec("kd_nm_s_per_rad", 0.5, 0.0, 50.0),
          spec("torque_max_nm", 5.0, 0.01, 500.0), spec("no_load_speed_rad_s", 0.0, 0.0, 100.0)};
}

// For a robot folder from a URDF (init-robot): the generic values, unless the URDF states the
// joint's effort: then the torque limit is that effort and kp gives it at 0.1 rad of error (a
// 20 N·m hobby leg joint gets 200 N·m/rad); the velocity limit becomes the no-load speed of the
// torque-speed curve. A leg joint of a floating-base robot (a foot below it) takes kp and kd
// from the robot's mass and leg geometry instead (stance_gains.hpp), and its torque limit too
// when the URDF's effort is missing or a placeholder, so a fresh robot stands.
std::vector<ParameterDefault> init_defaults(const RobotModel& model, std::size_t actuator,
                                            const JointHints& hints) {
  std::vector<ParameterDefault> out;
  const std::string law = "servo 'pd_torque' default";
  for (const ParameterSpec& spec : defaults(model, actuator)) {
    out.push_back({spec.name, spec.default_value, spec.lower, spec.upper, law});
  }
  if (std::isfinite(hints.effort) && hints.effort > 0.0) {
    const double effort = hints.effort;
    out[0] = {out[0].name, 10.0 * effort, 0.0, 1000.0 * effort, "URDF effort / 0.1 rad"};
    out[2] = {out[2].name, effort, 0.1 * effort, 10.0 * effort, "URDF effort"};
  }
  if (const auto stance = stance_gains(model, actuator)) {
    const std::string rule = "stance: (M·g/n_feet)·d = " + short_text(stance->hold_torque_nm) +
                             " N·m at d = " + short_text(stance->lever_m) + " m";
    out[0] = {out[0].name, stance->kp_nm_per_rad, 0.0, 10.0 * stance->kp_nm_per_rad,
              rule + ", / " + short_text(kStanceSag_rad) + " rad"};
    out[1] = {out[1].name, stance->kd_nm_s_per_rad, 0.0, 10.0 * stance->kd_nm_s_per_rad,
              "stance: critical damping of the weight share at d"};
    if (!(std::isfinite(hints.effort) && hints.effort > 0.0)) {
      out[2] = {out[2].name, stance->torque_max_nm, 0.1 * stance->torque_max_nm,
                10.0 * stance->torque_max_nm, rule + ", x 4"};
    }
  }
  if (std::isfinite(hints.velocity) && hints.velocity > 0.0) {
    out[3] = {out[3].name, hints.velocity, 0.0, 10.0 * hints.velocity, "URDF velocity"};
  }
  return out;
}

std::unique_ptr<ServoLaw> create(const ServoLawSetup& setup) {
  const ActuatorSpec& spec = setup.model.actuators[setup.actuator];
  const std::string prefix = servo_parameter_prefix(spec);
  PdTorqueParams p;
  p.kp_nm_per_rad = setup.get(prefix + "kp_nm_per_rad");
  p.kd_nm_s_per_rad = setup.get(prefix + "kd_nm_s_per_rad");
  p.torque_max_nm = setup.get(prefix + "torque_max_nm");
  p.no_load_speed_rad_s = setup.get(prefix + "no_load_speed_rad_s");
  if (p.kp_nm_per_rad < 0.0 || p.kd_nm_s_per_rad < 0.0 || p.torque_max_nm < 0.0 ||
      p.no_load_speed_rad_s < 0.0) {
    throw ModelError(prefix +
                     "{kp_nm_per_rad, kd_nm_s_per_rad, torque_max_nm, "
                     "no_load_speed_rad_s} must not be negative");
  }
  return std::make_unique<PdTorqueServoLaw>(
      p, read_friction(setup.get, spec.name, FrictionTerms::kFamily),
      read_armature(setup.get, spec));
}

}  // namespace

ServoLawInfo pd_torque_servo_law_info() {
  ServoLawInfo info{"pd_torque",
                    "torque PD: clip(kp(q_d - q) - kd q', +-torque_max, torque-speed curve)", names,
                    create};
  info.default_parameters = defaults;
  info.init_defaults = init_defaults;
  return info;
}

}  // namespace motoflex
