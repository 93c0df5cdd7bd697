#include "motoflex/sim/actuator/gear_train.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <stdexcept>
#include <string>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

// Symplectic Euler on an undamped spring is stable for ω·Δt_g < 2; 1.9 leaves a margin so that
// the numerical frequency error (which grows without bound as ω·Δt_g → 2) stays moderate.
constexpr double kStabilityLimit = 1.9;

void validate(const GearParams& params, double dt_s) {
  // Written as !(x > 0) / !(x >= 0) so that NaN is rejected too.
  if (!(dt_s > 0.0)) throw std::invalid_argument("GearTrain: dt_s must be > 0");
  if (!(params.mass_kg_m2 > 0.0)) throw std::invalid_argument("GearTrain: mass_kg_m2 must be > 0");
  if (!(params.backlash_rad >= 0.0)) {
    throw std::invalid_argument("GearTrain: backlash_rad must be >= 0");
  }
  if (!(params.spring_nm_per_rad >= 0.0)) {
    throw std::invalid_argument("GearTrain: spring_nm_per_rad must be >= 0");
  }
  if (!(params.viscous_nm_s_per_rad >= 0.0)) {
    throw std::invalid_argument("GearTrain: viscous_nm_s_per_rad must be >= 0");
  }
}

// The one stability predicate; the constructor and minimum_stable_substeps() must agree on it
// bit for bit, so both call this.
bool is_stable(const GearParams& params, double dt_s, int substeps) {
  return std::sqrt(params.spring_nm_per_rad / params.mass_kg_m2) * dt_s / substeps <
         kStabilityLimit;
}

}  // namespace

GearTrain::GearTrain(const GearParams& params, double dt_s, int substeps)
    : params_(params), substeps_(substeps), substep_s_(0.0) {
  validate(params, dt_s);
  if (substeps <= 0) throw std::invalid_argument("GearTrain: substeps must be > 0");
  if (!is_stable(params, dt_s, substeps)) {
    throw ModelError("GearTrain: " + std::to_string(substeps) +
                     " substeps per physics step are unstable for this gear spring and mass; "
                     "need at least " +
                     std::to_string(minimum_stable_substeps(params, dt_s)));
  }
  // Seed 001, Algorithm 2, line 2: Δt_g = Δt_s / substeps.
  substep_s_ = dt_s / substeps;
  const double per_mass_s2 = substep_s_ * substep_s_ / params.mass_kg_m2;
  damping_factor_ = 1.0 / (1.0 + params.viscous_nm_s_per_rad * substep_s_ / params.mass_kg_m2);
  drive_step_gain_ = params.ratio * per_mass_s2 * damping_factor_;
  spring_step_gain_ = params.spring_nm_per_rad * per_mass_s2 * damping_factor_;
  mean_torque_gain_ = params.spring_nm_per_rad / substeps;
}

double GearTrain::update(double motor_torque_nm) {
  // The velocity update of Algorithm 2 (lines 10–12, see the header), multiplied through by
  // Δt_g so the loop carries the position increment s = ṗ_m·Δt_g:
  //   s ← s·c_B + σ·T_M·Δt_g²/m_g·c_B − D_g·Δt_g²/m_g·c_B·p_h,   c_B = 1/(1 + B_g·Δt_g/m_g)
  //   p_m ← p_m + s
  // It is symplectic Euler (velocity first, then position with the new velocity) with the
  // viscous term implicit; the paper's explicit order gains energy on the spring at any Δt_g.
  // Line 1 (T_M' = σ·T_M) is folded into the drive increment.
  const double drive_step_rad = motor_torque_nm * drive_step_gain_;
  const double backlash_rad = params_.backlash_rad;
  double position_rad = position_rad_;
  double step_rad = velocity_rad_s_ * substep_s_;
  double summed_compression_rad = 0.0;
  for (int i = 0; i < substeps_; ++i) {  // Algorithm 2, line 2
    // Lines 3–9: for l_h >= 0 at most one term is nonzero (p_m > l_h: p_m − l_h; p_m < 0: p_m;
    // inside the hull: 0).
    const double compression_rad =
        std::max(position_rad - backlash_rad, 0.0) + std::min(position_rad, 0.0);
    // Line 13 (T_j += T_s·Δt_g/Δt_s); D_g/substeps is applied once after the loop.
    summed_compression_rad += compression_rad;
    step_rad = step_rad * damping_factor_ + drive_step_rad - spring_step_gain_ * compression_rad;
    position_rad += step_rad;
  }
  position_rad_ = position_rad;
  velocity_rad_s_ = step_rad / substep_s_;
  return summed_compression_rad * mean_torque_gain_;
}

void GearTrain::settle_at(double joint_torque_nm) {
  const double spring = params_.spring_nm_per_rad;
  if (joint_torque_nm == 0.0) {
    position_rad_ = 0.5 * params_.backlash_rad;  // the middle of the hull, touching neither side
  } else if (std::isnan(joint_torque_nm)) {
    throw std::invalid_argument("GearTrain::settle_at: torque is NaN");
  } else if (spring == 0.0) {
    throw ModelError("GearTrain::settle_at: a gear without spring cannot hold a torque");
  } else if (joint_torque_nm > 0.0) {
    position_rad_ = params_.backlash_rad + joint_torque_nm / spring;  // against the upper side
  } else {
    position_rad_ = joint_torque_nm / spring;  // against the lower side
  }
  velocity_rad_s_ = 0.0;
}

void GearTrain::set_state(double position_rad, double velocity_rad_s) {
  position_rad_ = position_rad;
  velocity_rad_s_ = velocity_rad_s;
}

int GearTrain::minimum_stable_substeps(const GearParams& params, double dt_s) {
  validate(params, dt_s);
  const double estimate =
      std::floor(std::sqrt(params.spring_nm_per_rad / params.mass_kg_m2) * dt_s / kStabilityLimit) +
      1.0;
  if (!(estimate < static_cast<double>(INT_MAX) - 2.0)) {
    throw ModelError("GearTrain: the gear spring is too stiff for any substep count");
  }
  // The closed form can be off by one where the ratio rounds; settle it with the predicate the
  // constructor uses.
  int substeps = std::max(1, static_cast<int>(estimate));
  while (substeps > 1 && is_stable(params, dt_s, substeps - 1)) --substeps;
  while (!is_stable(params, dt_s, substeps)) ++substeps;
  return substeps;
}

}  // namespace motoflex
