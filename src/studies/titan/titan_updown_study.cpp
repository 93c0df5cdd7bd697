// Seed 000 §VI: the sinusoidal up-and-down "calibration" motion. The joint work over a rise from
// bottom to top must equal the potential-energy gain, and over a whole period it must vanish.

#include <cmath>
#include <stdexcept>

#include "motoflex/studies/titan/titan_study.hpp"
#include "titan_study_run.hpp"

namespace motoflex {

TitanUpDownResult run_titan_updown(const TitanStudySetup& setup,
                                   const TitanUpDownStudyOptions& options) {
  detail::check_titan_study_setup(setup);
  if (options.motion.periods < 2) {
    throw std::invalid_argument("TITAN up-and-down study: needs at least 2 periods");
  }
  if (!(options.settle_s >= 0.0)) {
    throw std::invalid_argument("TITAN up-and-down study: settle_s must be >= 0");
  }
  const RobotModel& model = *setup.model;
  const TitanKinematics kinematics(model);
  const TitanUpDown plan(options.motion);
  const CommandTrajectory commands = detail::titan_study_commands(setup, kinematics, plan);
  const double dt = setup.rollout.dt_s;

  TitanUpDownResult result;
  std::vector<double> kinetic_j;
  double work_feedback = 0.0, work_active = 0.0, work_jacobian = 0.0;
  std::vector<double> work_active_j;
  const auto record_state = [&](double t, const TitanTorqueProbe& probe) {
    result.time_s.push_back(t);
    result.body_height_m.push_back(probe.rollout().torso_position_m().z());
    result.potential_j.push_back(probe.potential_energy_j());
    kinetic_j.push_back(probe.kinetic_energy_j());
    result.work_feedback_j.push_back(work_feedback);
    result.work_jacobian_j.push_back(work_jacobian);
    work_active_j.push_back(work_active);
  };
  const auto observe = [&](double t, const TitanTorqueProbe* probe) {
    for (const TitanLeg leg : kTitanLegs) {
      const TitanLegSample& s = probe->leg(leg);
      for (std::size_t j = 0; j < 4; ++j) {
        const double p = s.feedback_torque_nm[j] * s.rate_rad_s[j] * dt;
        work_feedback += p;
        if (j < 3) {
          work_active += p;
          work_jacobian += s.jacobian_torque_nm[j] * s.rate_rad_s[j] * dt;
        }
      }
    }
    record_state(t, *probe);
  };
  const detail::ProbeRunEnd end = detail::run_titan_probe_rollout(
      setup, kinematics, commands, options.settle_s, plan.duration_s(), true, observe);
  result.end = end.end;
  result.end_detail = end.detail;

  // The plan's height is mean + a·sin(2πt/T): the first bottom in the second period is at
  // 3T/4, the following top at 5T/4, and the next bottom at 7T/4.
  const double T = options.motion.period_s;
  result.rise_start_s = 0.75 * T;
  result.rise_end_s = 1.25 * T;
  const auto at = [&](double t) {  // sample k is the end of step k, at (k + 1)·dt
    return static_cast<std::size_t>(std::llround(t / dt)) - 1;
  };
  const std::size_t bottom = at(result.rise_start_s), top = at(result.rise_end_s),
                    next_bottom = at(1.75 * T);
  if (next_bottom >= result.time_s.size()) return result;  // ended early: fields stay 0
  result.potential_gain_j = result.potential_j[top] - result.potential_j[bottom];
  result.kinetic_change_j = kinetic_j[top] - kinetic_j[bottom];
  result.integrated_power_j = result.work_feedback_j[top] - result.work_feedback_j[bottom];
  result.integrated_power_active_j = work_active_j[top] - work_active_j[bottom];
  result.integrated_power_jacobian_j = result.work_jacobian_j[top] - result.work_jacobian_j[bottom];
  result.period_integral_j = result.work_feedback_j[next_bottom] - result.work_feedback_j[bottom];
  result.period_integral_jacobian_j =
      result.work_jacobian_j[next_bottom] - result.work_jacobian_j[bottom];
  return result;
}

}  // namespace motoflex
