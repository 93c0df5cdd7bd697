#include "motoflex/sim/actuator/gear_train.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

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

}  // namespace

GearTrain::GearTrain(const GearParams& params, double dt_s, int substeps)
    : params_(params), substeps_(substeps), substep_s_(0.0) {
  validate(params, dt_s);
  if (substeps <= 0) throw std::invalid_argument("GearTrain: substeps must be > 0");
  // Seed 001, Algorithm 2, line 2: Δt_g = Δt_s / substeps.
  substep_s_ = dt_s / substeps;
  const double per_mass_s2 = substep_s_ * substep_s_ / params.mass_kg_m2;
  const double damping = params.viscous_nm_s_per_rad * substep_s_ / params.mass_kg_m2;
  free_factor_ = 1.0 / (1.0 + damping);
  contact_factor_ = 1.0 / (1.0 + damping + params.spring_nm_per_rad * per_mass_s2);
  drive_step_gain_ = params.ratio * per_mass_s2;
  spring_step_gain_ = params.spring_nm_per_rad * per_mass_s2;
  mean_torque_gain_ = params.spring_nm_per_rad / substeps;
}

double GearTrain::update(double motor_torque_nm) {
  // The velocity update of the header, multiplied through by Δt_g so the loop carries the
  // position increment s = ṗ_m·Δt_g (line 1, T_M' = σ·T_M, is folded into the drive). A substep
  // is a contact substep when the mass touches the hull at its start or would touch it at its
  // end; the spring then acts implicitly from the touched wall e:
  //   contact: s ← (s + σ·T_M·Δt_g²/m_g − D_g·Δt_g²/m_g·(p_m − e))·c_contact
  //   free:    s ← (s + σ·T_M·Δt_g²/m_g)·c_free
  //   p_m ← p_m + s
  // so a mass that reaches the wall within a substep is caught there instead of overshooting
  // deep into the spring (which is what keeps any substep count stable).
  const double drive_step_rad = motor_torque_nm * drive_step_gain_;
  const double backlash_rad = params_.backlash_rad;
  double position_rad = position_rad_;
  double step_rad = velocity_rad_s_ * substep_s_;
  double summed_compression_rad = 0.0;
  for (int i = 0; i < substeps_; ++i) {  // Algorithm 2, line 2
    const double free_step_rad = (step_rad + drive_step_rad) * free_factor_;
    // Lines 3–9: which wall, if any, the mass touches now or would touch after a free substep.
    const double probe_rad = position_rad > backlash_rad || position_rad < 0.0
                                 ? position_rad
                                 : position_rad + free_step_rad;
    if (probe_rad > backlash_rad || probe_rad < 0.0) {
      const double wall_rad = probe_rad > backlash_rad ? backlash_rad : 0.0;
      step_rad = (step_rad + drive_step_rad - spring_step_gain_ * (position_rad - wall_rad)) *
                 contact_factor_;
    } else {
      step_rad = free_step_rad;
    }
    position_rad += step_rad;
    // Line 13 (T_j += T_s·Δt_g/Δt_s) with the spring force where the substep ends; D_g/substeps
    // is applied once after the loop.
    summed_compression_rad +=
        std::max(position_rad - backlash_rad, 0.0) + std::min(position_rad, 0.0);
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

}  // namespace motoflex
