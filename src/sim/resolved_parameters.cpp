#include "resolved_parameters.hpp"

#include <cmath>
#include <string>

#include "motoflex/core/error.hpp"
#include "motoflex/model/joint_units.hpp"

namespace motoflex::detail {
namespace {

bool has_flex_joints(const RobotModel& model) {
  for (const auto& j : model.joints) {
    if (j.kind == JointKind::kFlex) return true;
  }
  return false;
}

// Only shapes that collide with the ground read the contact parameters: a fixed-base arm
// whose links may not touch the ground needs none.
bool touches_ground(const RobotModel& model) {
  if (!model.ground) return false;
  for (const auto& body : model.bodies) {
    if (body.is_static) continue;
    for (const auto& shape : body.collisions) {
      if (shape.contact != GroundContact::kFall) return true;
    }
  }
  return false;
}

const char* const kBenchLoadNames[] = {"bench.mass_kg", "bench.length_m", "bench.armature_kg_m2"};
const char* const kFlexNames[] = {"flex.spring_nm_per_rad", "flex.damping_nm_s_per_rad",
                                  "flex.friction_nm"};
const char* const kContactNames[] = {"contact.mu", "contact.soft_erp", "contact.soft_cfm",
                                     "contact.slip"};
const char* const kWorldNames[] = {"world.erp", "world.cfm", "sensor.resolution_bits",
                                   "sensor.noise_rad", "sensor.delay_s"};

std::string encoder_offset_name(const ActuatorSpec& a) {
  return joint_parameter(a, "encoder_offset", joint_units(a).position);
}

std::string mounting_offset_name(const ActuatorSpec& a) {
  return joint_parameter(a, "mounting_offset", joint_units(a).position);
}

JointTorqueTerms read_torque_terms(const ParameterReader& get, const std::string& joint) {
  JointTorqueTerms out;
  for (const TorqueTerm& term : torque_terms()) {
    const double coefficient = get(term_parameter(joint, term.leaf));
    if (coefficient != 0.0) out.terms.emplace_back(&term, coefficient);
  }
  const std::string prefix = "joint." + joint + ".";
  TruthTorques& t = out.truth;
  t.cogging_nm = get(prefix + "cogging_nm");
  t.cogging_periods = get(prefix + "cogging_periods");
  t.cogging_phase_rad = get(prefix + "cogging_phase_rad");
  t.drag_nm_s2_per_rad2 = get(prefix + "drag_nm_s2_per_rad2");
  t.load_saturation_nm = get(prefix + "load_saturation_nm");
  t.load_saturation_scale_nm = get(prefix + "load_saturation_scale_nm");
  if (t.load_saturation_nm != 0.0 && !(t.load_saturation_scale_nm > 0.0)) {
    throw ModelError(prefix + "load_saturation_scale_nm must be positive");
  }
  return out;
}

}  // namespace

bool JointTorqueTerms::uses_load() const {
  for (const auto& [term, coefficient] : terms) {
    if (term->uses_load) return true;
  }
  return truth.load_saturation_nm != 0.0;
}

double JointTorqueTerms::torque_nm(const TermState& state) const {
  double sum_nm = truth.active() ? truth_torque_nm(truth, state) : 0.0;
  for (const auto& [term, coefficient] : terms) sum_nm += coefficient * term_value(*term, state);
  return sum_nm;
}

std::vector<std::string> rollout_wide_parameter_names(const RobotModel& model,
                                                      bool point_mass_arm) {
  std::vector<std::string> names;
  for (const auto& a : model.actuators) {
    names.push_back("joint." + a.name + ".encoder_scale");
    names.push_back(encoder_offset_name(a));
  }
  for (const auto& a : model.actuators) {
    for (const TorqueTerm& term : torque_terms())
      names.push_back(term_parameter(a.name, term.leaf));
    for (const std::string& leaf : truth_torque_leaves()) {
      names.push_back("joint." + a.name + "." + leaf);
    }
  }
  if (point_mass_arm)
    names.insert(names.end(), std::begin(kBenchLoadNames), std::end(kBenchLoadNames));
  if (has_flex_joints(model))
    names.insert(names.end(), std::begin(kFlexNames), std::end(kFlexNames));
  if (touches_ground(model)) {
    names.insert(names.end(), std::begin(kContactNames), std::end(kContactNames));
  }
  names.insert(names.end(), std::begin(kWorldNames), std::end(kWorldNames));
  // Appended, so that the names above keep their order in parameter files.
  for (const auto& a : model.actuators) names.push_back(mounting_offset_name(a));
  return names;
}

ResolvedParameters resolve_parameters(const RobotModel& model, const ParameterSet& values,
                                      bool point_mass_arm) {
  const ParameterReader get(values, "(rollout)");
  ResolvedParameters out;
  out.encoders.resize(model.actuators.size());
  for (std::size_t i = 0; i < model.actuators.size(); ++i) {
    const std::string joint = "joint." + model.actuators[i].name + ".";
    out.encoders[i] = {get(joint + "encoder_scale"), get(encoder_offset_name(model.actuators[i])),
                       get(mounting_offset_name(model.actuators[i]))};
    out.torque_terms.push_back(read_torque_terms(get, model.actuators[i].name));
  }
  if (point_mass_arm) {
    out.bench_load = {get("bench.mass_kg"), get("bench.length_m"), get("bench.armature_kg_m2")};
    if (!(out.bench_load.mass_kg > 0.0) || !(out.bench_load.length_m > 0.0) ||
        out.bench_load.armature_kg_m2 < 0.0) {
      throw ModelError("bench mass and length must be positive, armature not negative");
    }
  }
  if (has_flex_joints(model)) {
    out.flex = {get("flex.spring_nm_per_rad"), get("flex.damping_nm_s_per_rad"),
                get("flex.friction_nm")};
    if (!(out.flex.spring_nm_per_rad > 0.0) || out.flex.damping_nm_s_per_rad < 0.0 ||
        out.flex.friction_nm < 0.0) {
      throw ModelError("flex.spring_nm_per_rad must be positive, damping and friction >= 0");
    }
  }
  if (touches_ground(model)) {
    out.contact = {get("contact.mu"), get("contact.soft_erp"), get("contact.soft_cfm"),
                   get("contact.slip")};
  }
  out.world_erp = get("world.erp");
  out.world_cfm = get("world.cfm");
  out.encoder.resolution_bits = static_cast<int>(std::lround(get("sensor.resolution_bits")));
  out.encoder.noise_rad = get("sensor.noise_rad");
  out.encoder.delay_s = get("sensor.delay_s");
  return out;
}

}  // namespace motoflex::detail
