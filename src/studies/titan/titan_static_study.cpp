// Seed 000 §III: static standing in the standard posture, knee (J3) load and torque from joint
// feedback (eq. 4–5) and from the J4 force (eq. 7), and how fast each settles (Fig. 5).

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "motoflex/studies/titan/settling.hpp"
#include "motoflex/studies/titan/titan_study.hpp"
#include "titan_study_run.hpp"

namespace motoflex {
namespace {

// Footnote 2: the knee carries everything but the shanks and feet, shared by four legs.
double expected_knee_force_n(const RobotModel& model, const TitanKinematics& kinematics,
                             double gravity_m_s2) {
  double total = 0.0;
  for (const BodySpec& body : model.bodies) total += body.mass_kg;
  double below_knees = 0.0;
  for (const TitanLeg leg : kTitanLegs) {
    for (const std::size_t j : {2u, 3u}) {  // J3 → shank, J4 → foot
      const ActuatorSpec& actuator = model.actuators[kinematics.actuators(leg)[j]];
      below_knees += model.bodies[model.joints[actuator.joint].child_body].mass_kg;
    }
  }
  return (total - below_knees) * gravity_m_s2 / 4.0;
}

// The knee load components the result keeps only as final means.
struct KneeLoadSeries {
  std::array<std::vector<double>, 4> fx, fy, mx, my, mz;
};

// One leg's final means, landing peak, knee-vs-ankle gap and settling times, measured after
// the touchdown plus the cut.
void summarise_leg(std::size_t l, const TitanStaticOptions& options, const KneeLoadSeries& loads,
                   TitanStaticResult& result) {
  const double window = options.final_window_s;
  const double from = result.touchdown_s + options.cut_after_touchdown_s;
  const auto band = [&](double final_value) {
    return options.converge_fraction *
           std::max(std::abs(final_value), options.converge_reference_nm);
  };
  const std::vector<double>& t = result.time_s;
  result.knee_force_n[l] = {tail_mean(t, loads.fx[l], window), tail_mean(t, loads.fy[l], window),
                            tail_mean(t, result.knee_fz_series_n[l], window)};
  result.knee_moment_nm[l] = {tail_mean(t, loads.mx[l], window), tail_mean(t, loads.my[l], window),
                              tail_mean(t, loads.mz[l], window)};
  result.knee_feedback_nm[l] = tail_mean(t, result.knee_feedback_series_nm[l], window);
  result.knee_jacobian_nm[l] = tail_mean(t, result.knee_jacobian_series_nm[l], window);
  result.ankle_feedback_nm[l] = tail_mean(t, result.ankle_feedback_series_nm[l], window);
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] >= result.touchdown_s && t[k] < from &&
        std::abs(result.knee_feedback_series_nm[l][k]) > std::abs(result.landing_peak_nm[l])) {
      result.landing_peak_nm[l] = result.knee_feedback_series_nm[l][k];
    }
    if (t[k] < from) continue;
    const double gap = result.knee_feedback_series_nm[l][k] - result.knee_jacobian_series_nm[l][k] -
                       result.ankle_feedback_series_nm[l][k];
    result.max_knee_gap_beyond_ankle_nm =
        std::max(result.max_knee_gap_beyond_ankle_nm, std::abs(gap));
  }
  result.feedback_converge_s[l] =
      settling_time_s(t, result.knee_feedback_series_nm[l], result.knee_feedback_nm[l],
                      band(result.knee_feedback_nm[l]), from) -
      result.touchdown_s;
  result.jacobian_converge_s[l] =
      settling_time_s(t, result.knee_jacobian_series_nm[l], result.knee_jacobian_nm[l],
                      band(result.knee_jacobian_nm[l]), from) -
      result.touchdown_s;
  const double fz = result.knee_force_n[l].z();
  result.fz_converge_s[l] = settling_time_s(t, result.knee_fz_series_n[l], fz,
                                            options.converge_fraction * std::abs(fz), from) -
                            result.touchdown_s;
}

}  // namespace

TitanStaticResult run_titan_static(const TitanStudySetup& setup,
                                   const TitanStaticOptions& options) {
  detail::check_titan_study_setup(setup);
  if (!(options.duration_s > 0.0 && options.cut_after_touchdown_s >= 0.0 &&
        options.converge_fraction > 0.0 && options.converge_reference_nm >= 0.0 &&
        options.final_window_s > 0.0 && options.final_window_s < options.duration_s)) {
    throw std::invalid_argument("TITAN static study: invalid options");
  }
  const RobotModel& model = *setup.model;
  const TitanKinematics kinematics(model);
  const TitanStand plan(options.posture, options.duration_s);
  const CommandTrajectory commands = detail::titan_study_commands(setup, kinematics, plan);

  TitanStaticResult result;
  result.touchdown_s = std::numeric_limits<double>::quiet_NaN();
  KneeLoadSeries loads;
  double gravity_m_s2 = 0.0;
  const auto observe = [&](double t, const TitanTorqueProbe* probe) {
    if (result.time_s.empty()) {
      gravity_m_s2 = probe->rollout().gravity_m_s2().norm();
    }
    result.time_s.push_back(t);
    for (const TitanLeg leg : kTitanLegs) {
      const auto l = static_cast<std::size_t>(leg);
      const TitanLegSample& s = probe->leg(leg);
      result.knee_feedback_series_nm[l].push_back(s.feedback_torque_nm[2]);
      result.knee_jacobian_series_nm[l].push_back(s.jacobian_torque_nm[2]);
      result.knee_fz_series_n[l].push_back(s.knee_load.force_n.z());
      result.ankle_feedback_series_nm[l].push_back(s.feedback_torque_nm[3]);
      loads.fx[l].push_back(s.knee_load.force_n.x());
      loads.fy[l].push_back(s.knee_load.force_n.y());
      loads.mx[l].push_back(s.knee_load.moment_nm.x());
      loads.my[l].push_back(s.knee_load.moment_nm.y());
      loads.mz[l].push_back(s.knee_load.moment_nm.z());
      result.max_third_law_residual_n =
          std::max(result.max_third_law_residual_n, s.knee_third_law_residual_n);
      if (std::isnan(result.touchdown_s) && probe->foot_clearance_m(leg) <= 0.0) {
        result.touchdown_s = t;
      }
    }
  };
  const detail::ProbeRunEnd end = detail::run_titan_probe_rollout(
      setup, kinematics, commands, 0.0, options.duration_s, true, observe);
  result.end = end.end;
  result.end_detail = end.detail;

  result.expected_knee_fz_n = expected_knee_force_n(model, kinematics, gravity_m_s2);
  if (result.time_s.empty() || std::isnan(result.touchdown_s)) return result;

  for (std::size_t l = 0; l < 4; ++l) summarise_leg(l, options, loads, result);
  return result;
}

}  // namespace motoflex
