#pragma once

// Internal to the rollout: a ParameterSet turned into the typed values each stage reads, once
// per rollout, so the physics step never looks a name up.

#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/sim/actuator/dc_motor.hpp"
#include "motoflex/sim/actuator/gear_train.hpp"
#include "motoflex/sim/actuator/pid.hpp"
#include "motoflex/sim/actuator/servo_laws.hpp"
#include "motoflex/sim/joint_encoder.hpp"

namespace motoflex::detail {

struct ActuatorParameters {
  PidGains pid;
  DcMotorParams motor;
  GearParams gear;
  JointFrictionParams friction;
  VelocityServoParams velocity;
  BenchServoParams bench;
  // Algorithm 1's B·ω_m reflected to the joint: B·σ² (N·m·s/rad), a true damper applied
  // implicitly by its own ODE motor row (motoflex servo only; zero otherwise).
  double back_emf_damping_nm_s_per_rad = 0.0;
  // What the logging encoder reports: scale·θ + offset (then delay, quantisation, noise). The
  // servo regulates the true angle; these are calibration errors of the reported angle.
  double encoder_scale = 1.0;
  double encoder_offset_rad = 0.0;
};

struct FlexParameters {
  double spring_nm_per_rad = 0.0;
  double damping_nm_s_per_rad = 0.0;
  double friction_nm = 0.0;
};

struct ContactParameters {
  double mu = 1.0;
  double soft_erp = 0.2;
  double soft_cfm = 1e-4;
  double slip = 0.0;
};

struct BenchLoad {
  double mass_kg = 0.0;
  double length_m = 0.0;
  double armature_kg_m2 = 0.0;
};

struct ResolvedParameters {
  std::vector<ActuatorParameters> actuators;  // model actuator order
  IdealServoParams ideal;
  FlexParameters flex;
  ContactParameters contact;
  double world_erp = 0.2;
  double world_cfm = 1e-10;
  EncoderParams encoder;
  BenchLoad bench_load;
  // Effects on the motors (motoflex servo): R(t) = R·(1 + drift·t) as the windings heat up, and
  // a battery with internal resistance: U_bat(t) = U_bat − R_int·Σ|I| over all motors.
  double motor_resistance_drift_per_s = 0.0;
  double supply_sag_ohm = 0.0;
};

// Reads what `servo` needs (plus flex, contact, world and sensor values). Throws ModelError
// naming the first parameter the model does not declare.
ResolvedParameters resolve_parameters(const RobotModel& model, const ParameterSet& values,
                                      ServoKind servo);

}  // namespace motoflex::detail
