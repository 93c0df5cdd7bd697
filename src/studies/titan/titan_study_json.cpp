#include <algorithm>
#include <cmath>

#include "motoflex/studies/titan/titan_study_report.hpp"

namespace motoflex {
namespace {

using Json = nlohmann::ordered_json;

Json number(double value) {
  return std::isfinite(value) ? Json(value) : Json(nullptr);
}

template <std::size_t N>
Json numbers(const std::array<double, N>& values) {
  Json out = Json::array();
  for (const double v : values) out.push_back(number(v));
  return out;
}

Json vector3(const Eigen::Vector3d& v) {
  return Json::array({v.x(), v.y(), v.z()});
}

template <std::size_t N>
double max_of(const std::array<double, N>& values) {
  double out = -INFINITY;
  for (const double v : values) out = std::max(out, v);  // +inf (never settled) wins
  return out;
}

Json static_json(const TitanStaticOptions& options, const TitanStaticResult& r) {
  double fz_sum = 0.0, other_force = 0.0, other_moment = 0.0;
  for (std::size_t l = 0; l < 4; ++l) {
    fz_sum += r.knee_force_n[l].z();
    other_force =
        std::max({other_force, std::abs(r.knee_force_n[l].x()), std::abs(r.knee_force_n[l].y())});
    other_moment = std::max(other_moment, r.knee_moment_nm[l].cwiseAbs().maxCoeff());
  }
  Json j;
  j["knee_fz_n"] = fz_sum / 4.0;
  j["knee_other_max"] = std::max(other_force, other_moment);
  j["feedback_converge_s"] = number(max_of(r.feedback_converge_s));
  j["jacobian_converge_s"] = number(max_of(r.jacobian_converge_s));
  j["note"] =
      "knee load in the paper's sign (force/moment the shank exerts on the knee); knee_fz_n is "
      "the mean over the legs; knee_other_max is the largest final |Fx|, |Fy| [N] or "
      "|Mx|, |My|, |Mz| [N m] of any knee; converge times are from touchdown until the J3 "
      "torque stays within the band of its final value, slowest leg";
  j["knee_fz_expected_n"] = r.expected_knee_fz_n;
  j["knee_fz_per_leg_n"] = Json::array();
  for (const auto& f : r.knee_force_n) j["knee_fz_per_leg_n"].push_back(f.z());
  j["knee_other_force_max_n"] = other_force;
  j["knee_other_moment_max_nm"] = other_moment;
  j["knee_force_FL_n"] = vector3(r.knee_force_n[0]);
  j["knee_moment_FL_nm"] = vector3(r.knee_moment_nm[0]);
  j["knee_torque_feedback_nm"] = numbers(r.knee_feedback_nm);
  j["knee_torque_jacobian_nm"] = numbers(r.knee_jacobian_nm);
  j["ankle_torque_feedback_nm"] = numbers(r.ankle_feedback_nm);
  j["feedback_converge_per_leg_s"] = numbers(r.feedback_converge_s);
  j["jacobian_converge_per_leg_s"] = numbers(r.jacobian_converge_s);
  j["knee_fz_converge_per_leg_s"] = numbers(r.fz_converge_s);
  j["converge_band_nm"] = options.converge_fraction *
                          std::max(std::abs(r.knee_feedback_nm[0]), options.converge_reference_nm);
  j["cut_after_touchdown_s"] = options.cut_after_touchdown_s;
  j["touchdown_s"] = number(r.touchdown_s);
  j["landing_peak_knee_nm"] = numbers(r.landing_peak_nm);
  j["duration_s"] = options.duration_s;
  j["third_law_residual_max_n"] = r.max_third_law_residual_n;
  j["knee_gap_beyond_ankle_max_nm"] = r.max_knee_gap_beyond_ankle_nm;
  j["end"] = to_string(r.end);
  if (!r.end_detail.empty()) j["end_detail"] = r.end_detail;
  return j;
}

Json updown_json(const TitanUpDownStudyOptions& options, const TitanUpDownResult& r) {
  Json j;
  j["potential_gain_j"] = r.potential_gain_j;
  j["integrated_power_j"] = r.integrated_power_j;
  j["period_integral_j"] = r.period_integral_j;
  const double rise = r.potential_gain_j + r.kinetic_change_j;
  j["rise_error_percent"] =
      number(100.0 * (r.integrated_power_j - rise) / std::abs(r.potential_gain_j));
  j["period_integral_percent_of_rise"] =
      number(100.0 * r.period_integral_j / std::abs(r.potential_gain_j));
  j["kinetic_change_j"] = r.kinetic_change_j;
  j["integrated_power_active_j"] = r.integrated_power_active_j;
  j["integrated_power_jacobian_j"] = r.integrated_power_jacobian_j;
  j["period_integral_jacobian_j"] = r.period_integral_jacobian_j;
  j["rise_start_s"] = r.rise_start_s;
  j["rise_end_s"] = r.rise_end_s;
  j["amplitude_m"] = options.motion.amplitude_m;
  j["period_s"] = options.motion.period_s;
  j["note"] =
      "integrated_power_j: all 16 servos, feedback torques (eq. 4-5); _active: J1-J3; "
      "_jacobian: J1-J3 with eq. 7 (leg masses neglected)";
  j["end"] = to_string(r.end);
  if (!r.end_detail.empty()) j["end_detail"] = r.end_detail;
  return j;
}

Json power_json(const TitanPowerSummary& p) {
  Json j;
  j["avg_abs_power_w"] = p.total_w;
  j["J1_w"] = p.joint_w[0];
  j["J2_w"] = p.joint_w[1];
  j["J3_w"] = p.joint_w[2];
  return j;
}

Json crawl_json(const TitanCrawlResult& r) {
  Json j = power_json(r.jacobian);
  j["per_leg_w"] = Json::object();
  for (const TitanLeg leg : kTitanLegs) {
    const auto& w = r.jacobian.leg_joint_w[static_cast<std::size_t>(leg)];
    j["per_leg_w"][to_string(leg)] = Json::array({w[0], w[1], w[2]});
  }
  j["feedback"] = power_json(r.feedback);
  j["serial_jacobian"] = power_json(r.jacobian_serial);
  Json exchange;
  exchange["work_J2_j"] = r.exchange_work_j2_j;
  exchange["work_J3_j"] = r.exchange_work_j3_j;
  exchange["mean_abs_power_J2_w"] = r.exchange_mean_abs_power_j2_w;
  exchange["mean_abs_power_J3_w"] = r.exchange_mean_abs_power_j3_w;
  exchange["power_correlation"] = r.exchange_power_correlation;
  j["exchange_window"] = exchange;
  j["advance_m"] = r.advance_m;
  j["duration_s"] = r.duration_s;
  j["wall_s"] = r.wall_s;
  j["end"] = to_string(r.end);
  if (!r.end_detail.empty()) j["end_detail"] = r.end_detail;
  return j;
}

}  // namespace

nlohmann::ordered_json titan_study_json(const TitanStudyConfig& config,
                                        const TitanPaperStudyResults& results) {
  const TitanPaperStudyPlan& plan = config.plan;
  Json root;
  root["study"] = config.name;
  root["config"] = config.path;
  root["static"] = static_json(plan.stand, results.stand);
  root["updown"] = updown_json(plan.updown, results.updown);
  Json crawl = Json::object();  // posture keys only
  for (const TitanCrawlResult& r : results.crawls) crawl[to_string(r.posture)] = crawl_json(r);
  root["crawl"] = crawl;
  Json crawl_settings;
  crawl_settings["periods"] = plan.crawl.periods;
  crawl_settings["plot_leg"] = to_string(plan.crawl.plot_leg);
  crawl_settings["exchange_window_s"] = {plan.crawl.exchange_from_s, plan.crawl.exchange_to_s};
  crawl_settings["note"] =
      "avg_abs_power_w: eq. 8 averaged absolute power over the periods, 4 legs x J1-J3, "
      "parallel-link knee (eq. 1), eq. 7 torques (the paper's method); J1_w..J3_w: the same per "
      "joint, summed over the legs; 'feedback': eq. 4-5 torques; 'serial_jacobian': eq. 7 in "
      "the model's serial coordinates. exchange_window: plot leg, J2/J3 power in the window of "
      "every cycle (mean work per cycle, mean |P|, correlation of P2 and P3)";
  root["crawl_settings"] = crawl_settings;
  if (results.timing) {
    const TitanCrawlTiming& t = *results.timing;
    root["sim_seconds_per_10s_crawl"] = t.wall_s * 10.0 / t.simulated_s;
    Json timing;
    timing["note"] =
        "wall seconds to simulate 10 s of crawl in one thread (with the torque probe), fastest "
        "of wall_runs_s; the paper: 60 s on a 2011 PC";
    timing["simulated_s"] = t.simulated_s;
    timing["wall_s"] = t.wall_s;
    timing["wall_runs_s"] = t.wall_runs_s;
    timing["cpu_s"] = t.cpu_s;
    timing["wall_without_probe_s"] = t.wall_bare_s;
    timing["steps"] = t.steps;
    timing["steps_per_s"] = static_cast<double>(t.steps) / t.wall_s;
    root["timing"] = timing;
  } else {
    root["sim_seconds_per_10s_crawl"] = nullptr;
  }
  root["study_wall_s"] = results.wall_s;
  Json paper;
  paper["knee_fz_n"] = 49.1;
  paper["knee_other"] = "converge to 0";
  paper["feedback_converge_s"] = 2.0;
  paper["jacobian_converge_s"] = "about 5x faster than feedback (~0.4 s, read from the text)";
  paper["updown"] = "integrated power over the rise = potential-energy gain; over a period = 0";
  paper["crawl"] =
      "posture A (GDA) lowest averaged power, single-digit watts in ODE; B-D: J2 and J3 "
      "powers mirror each other in 2.4-4.8 s; Fig. 10 values not in the text";
  paper["sim_seconds_per_10s_crawl"] = 60.0;
  root["paper"] = paper;
  return root;
}

}  // namespace motoflex
