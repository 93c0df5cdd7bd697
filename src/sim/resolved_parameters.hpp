#pragma once

// Internal to the rollout: the rollout-wide part of a ParameterSet (contacts, world, sensors,
// flexible links, per-joint encoder calibration) turned into typed values once per rollout, so
// the physics step never looks a name up. Each servo law reads its own parameters
// (servo_law.hpp).

#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/model/torque_terms.hpp"
#include "motoflex/sim/actuator/servo_law.hpp"
#include "motoflex/sim/joint_encoder.hpp"

namespace motoflex::detail {

struct EncoderCalibration {
  // What the joint's encoder reads: θ + mounting_offset, θ the joint's angle from the pose the
  // model was built in (where the load hangs). The servo regulates on that reading. The log
  // reports scale·reading + offset (then delay, quantisation, noise): scale and offset are
  // calibration errors of the reported angle only.
  double scale = 1.0;
  double offset_rad = 0.0;
  double mounting_offset_rad = 0.0;
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

// The extra torques of one actuated joint (torque_terms.hpp): the discovered terms with a
// non-zero coefficient and the truth-side torques.
struct JointTorqueTerms {
  std::vector<std::pair<const TorqueTerm*, double>> terms;  // term, coefficient
  TruthTorques truth;
  bool active() const { return !terms.empty() || truth.active(); }
  bool uses_load() const;
  double torque_nm(const TermState& state) const;
};

struct ResolvedParameters {
  std::vector<EncoderCalibration> encoders;  // model actuator order
  FlexParameters flex;
  ContactParameters contact;
  double world_erp = 0.2;
  double world_cfm = 1e-10;
  EncoderParams encoder;
  BenchLoad bench_load;                        // laws with a point-mass arm only
  std::vector<JointTorqueTerms> torque_terms;  // model actuator order
};

// Reads the rollout-wide values (plus the bench arm when the first actuator's law has one,
// `point_mass_arm`). Throws ModelError naming the first parameter the model does not declare,
// or a value that cannot be simulated.
ResolvedParameters resolve_parameters(const RobotModel& model, const ParameterSet& values,
                                      bool point_mass_arm);

// The names resolve_parameters reads for `model` (rollout-wide names, not the laws' own).
std::vector<std::string> rollout_wide_parameter_names(const RobotModel& model, bool point_mass_arm);

}  // namespace motoflex::detail
