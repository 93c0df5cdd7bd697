#include "motoflex/sim/actuator/friction_family.hpp"

#include <cmath>
#include <utility>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

// The order of friction_parameter_names; the first kSpeedOnlyCount are read by kSpeedOnly, the
// first kMotorLoadCount by kMotorLoad (these keep the names the laws read before the family).
const char* const kLeaves[] = {"friction_nm",
                               "viscous_nm_s_per_rad",
                               "stribeck_nm",
                               "stribeck_velocity_rad_s",
                               "stribeck_exponent",
                               "load_friction",
                               "load_friction_external",
                               "load_friction_stribeck",
                               "load_friction_external_stribeck",
                               "load_friction_quad_per_nm",
                               "load_friction_external_quad_per_nm",
                               "friction_model",
                               "backdrive_friction",
                               "backdrive_friction_static"};
constexpr std::size_t kSpeedOnlyCount = 5;
constexpr std::size_t kMotorLoadCount = 6;
constexpr std::size_t kFamilyCount = std::size(kLeaves);

std::size_t leaf_count(FrictionTerms terms) {
  switch (terms) {
    case FrictionTerms::kSpeedOnly:
      return kSpeedOnlyCount;
    case FrictionTerms::kMotorLoad:
      return kMotorLoadCount;
    case FrictionTerms::kFamily:
      return kFamilyCount;
  }
  return 0;
}

// The coefficients `params.model` has, the others zeroed and M3/M4's single load coefficient
// applied to both torques (bam.md §2d: M3/M4 use |τ_m − τ_e|).
FrictionParams effective(const FrictionParams& p) {
  FrictionParams e = p;
  const int model = static_cast<int>(p.model);
  if (model < 6) e.quad_motor_per_nm = e.quad_external_per_nm = 0.0;
  if (model == 3 || model == 4) {
    e.load_external = e.load_motor;
    e.load_stribeck_external = e.load_stribeck_motor = model == 4 ? p.load_stribeck_motor : 0.0;
  }
  if (model <= 2) e.load_motor = e.load_external = 0.0;
  if (model <= 3) e.load_stribeck_motor = e.load_stribeck_external = 0.0;
  if (model == 1 || model == 3) e.stribeck_nm = 0.0;
  return e;
}

// BAM's Stribeck shape s(θ̇) = exp(−|θ̇/v_s|^α). α = 2 is written as u·u: the Gaussian the
// laws used before the family, bit for bit.
double stribeck_shape(const FrictionParams& p, double velocity_rad_s) {
  const double u = velocity_rad_s / p.stribeck_velocity_rad_s;
  if (p.stribeck_exponent == 2.0) return std::exp(-u * u);
  return std::exp(-std::pow(std::abs(u), p.stribeck_exponent));
}

// M6's quadratic term Q (0 unless the motor and the external torque oppose each other).
double quadratic_term(const FrictionParams& p, double motor_nm, double external_nm) {
  if (!(motor_nm * external_nm < 0.0)) return 0.0;
  if (std::abs(motor_nm) > std::abs(external_nm))
    return p.quad_external_per_nm * external_nm * external_nm;
  if (std::abs(motor_nm) < std::abs(external_nm)) return p.quad_motor_per_nm * motor_nm * motor_nm;
  return 0.0;
}

// Whether the load drives the joint: the motor torque does not push the way the joint moves, or
// would move at standstill (below 1 mrad/s ODE's stuck joint creeps; the net torque decides).
bool load_drives(double velocity_rad_s, double motor_torque_nm, double external_torque_nm) {
  constexpr double kStandstill_rad_s = 1.0e-3;
  const double direction = std::abs(velocity_rad_s) > kStandstill_rad_s
                               ? velocity_rad_s
                               : motor_torque_nm + external_torque_nm;
  return motor_torque_nm * direction <= 0.0;
}

}  // namespace

double friction_budget_nm(const FrictionParams& params, double velocity_rad_s,
                          double motor_torque_nm, double external_torque_nm) {
  const FrictionParams p = effective(params);
  // The order of the sums is the one of the laws before the family (Coulomb + viscous, then
  // Stribeck, then load), so that their results stay bit-identical.
  double budget_nm = p.coulomb_nm + p.viscous_nm_s_per_rad * std::abs(velocity_rad_s);
  const double stribeck_nm =
      p.stribeck_nm + std::abs(p.load_stribeck_motor * motor_torque_nm -
                               p.load_stribeck_external * external_torque_nm);
  const bool quadratic = p.quad_motor_per_nm != 0.0 || p.quad_external_per_nm != 0.0;
  const double shape = stribeck_nm != 0.0 || quadratic ? stribeck_shape(p, velocity_rad_s) : 0.0;
  if (stribeck_nm != 0.0) budget_nm += stribeck_nm * shape;
  budget_nm += std::abs(p.load_motor * motor_torque_nm - p.load_external * external_torque_nm);
  if (quadratic) budget_nm += shape * quadratic_term(p, motor_torque_nm, external_torque_nm);
  if ((p.backdrive != 0.0 || p.backdrive_static != 0.0) &&
      load_drives(velocity_rad_s, motor_torque_nm, external_torque_nm)) {
    const double static_part =
        p.backdrive_static != 0.0 ? p.backdrive_static * stribeck_shape(p, velocity_rad_s) : 0.0;
    budget_nm += (p.backdrive + static_part) * std::abs(external_torque_nm);
  }
  return budget_nm;
}

MotorCommand joint_friction(const FrictionParams& params, double velocity_rad_s,
                            double motor_torque_nm, double external_torque_nm) {
  return MotorCommand{
      0.0, friction_budget_nm(params, velocity_rad_s, motor_torque_nm, external_torque_nm)};
}

bool friction_reads_external_torque(const FrictionParams& params) {
  const FrictionParams p = effective(params);
  return p.load_external != 0.0 || p.load_stribeck_external != 0.0 || p.quad_motor_per_nm != 0.0 ||
         p.quad_external_per_nm != 0.0 || p.backdrive != 0.0 || p.backdrive_static != 0.0;
}

namespace {

void check_friction(const FrictionParams& f, const std::string& prefix) {
  for (const double coefficient :
       {f.coulomb_nm, f.viscous_nm_s_per_rad, f.stribeck_nm, f.load_motor, f.load_external,
        f.load_stribeck_motor, f.load_stribeck_external, f.quad_motor_per_nm,
        f.quad_external_per_nm, f.backdrive, f.backdrive_static}) {
    if (coefficient < 0.0) {
      throw ModelError("friction parameters of " + prefix + "* must not be negative");
    }
  }
  if (!(f.stribeck_velocity_rad_s > 0.0) || !(f.stribeck_exponent > 0.0)) {
    throw ModelError(prefix + "stribeck_velocity_rad_s and " + prefix +
                     "stribeck_exponent must be > 0");
  }
}

// A prismatic joint's force-like leaves in N and m (joint_units); the others are ratios.
std::string leaf_name(const char* leaf, bool prismatic) {
  static const std::pair<const char*, const char*> kSlider[] = {
      {"friction_nm", "friction_n"},
      {"viscous_nm_s_per_rad", "viscous_n_s_per_m"},
      {"stribeck_nm", "stribeck_n"},
      {"stribeck_velocity_rad_s", "stribeck_velocity_m_s"},
      {"load_friction_quad_per_nm", "load_friction_quad_per_n"},
      {"load_friction_external_quad_per_nm", "load_friction_external_quad_per_n"}};
  if (prismatic) {
    for (const auto& [hinge, slider] : kSlider) {
      if (std::string(leaf) == hinge) return slider;
    }
  }
  return leaf;
}

std::vector<std::string> names_of(const std::string& joint, bool prismatic, FrictionTerms terms) {
  std::vector<std::string> names;
  const std::size_t count = leaf_count(terms);
  for (std::size_t i = 0; i < count; ++i) {
    names.push_back("joint." + joint + "." + leaf_name(kLeaves[i], prismatic));
  }
  return names;
}

FrictionParams read_named(const ParameterReader& get, const std::string& joint, bool prismatic,
                          FrictionTerms terms) {
  const std::string prefix = "joint." + joint + ".";
  const auto value = [&](const char* leaf) { return get(prefix + leaf_name(leaf, prismatic)); };
  FrictionParams f;
  f.coulomb_nm = value("friction_nm");
  f.viscous_nm_s_per_rad = value("viscous_nm_s_per_rad");
  f.stribeck_nm = value("stribeck_nm");
  f.stribeck_velocity_rad_s = value("stribeck_velocity_rad_s");
  f.stribeck_exponent = value("stribeck_exponent");
  if (terms != FrictionTerms::kSpeedOnly) f.load_motor = value("load_friction");
  if (terms == FrictionTerms::kFamily) {
    f.load_external = value("load_friction_external");
    f.load_stribeck_motor = value("load_friction_stribeck");
    f.load_stribeck_external = value("load_friction_external_stribeck");
    f.quad_motor_per_nm = value("load_friction_quad_per_nm");
    f.quad_external_per_nm = value("load_friction_external_quad_per_nm");
    const double model = value("friction_model");
    if (!(model >= 1.0 && model <= 6.0 && std::round(model) == model)) {
      throw ModelError(prefix + "friction_model must be 1-6 (BAM's M1-M6)");
    }
    f.model = static_cast<FrictionModel>(static_cast<int>(model));
    f.backdrive = value("backdrive_friction");
    f.backdrive_static = value("backdrive_friction_static");
  }
  check_friction(f, prefix);
  return f;
}

}  // namespace

std::vector<std::string> friction_parameter_names(const std::string& joint, FrictionTerms terms) {
  return names_of(joint, false, terms);
}

std::vector<std::string> friction_parameter_names(const ActuatorSpec& joint, FrictionTerms terms) {
  return names_of(joint.name, joint.prismatic, terms);
}

FrictionParams read_friction(const ParameterReader& get, const std::string& joint,
                             FrictionTerms terms) {
  return read_named(get, joint, false, terms);
}

FrictionParams read_friction(const ParameterReader& get, const ActuatorSpec& joint,
                             FrictionTerms terms) {
  return read_named(get, joint.name, joint.prismatic, terms);
}

}  // namespace motoflex
