#include "motoflex/studies/titan/titan_study_report.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/io/plot_script.hpp"

namespace motoflex {
namespace {

std::string fmt(double value, int decimals = 3) {
  if (!std::isfinite(value)) return "never";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
  return buffer;
}

// Three significant digits, for numbers that may be tiny.
std::string fmt_g(double value) {
  if (!std::isfinite(value)) return "never";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.3g", value);
  return buffer;
}

double max_leg(const std::array<double, 4>& values) {
  return *std::max_element(values.begin(), values.end());  // +inf (never settled) wins
}

void static_section(std::ostream& md, const TitanStaticOptions& o, const TitanStaticResult& r,
                    const nlohmann::ordered_json& j, double clearance_m) {
  const double fb = max_leg(r.feedback_converge_s), jac = max_leg(r.jacobian_converge_s);
  md << "## Static standing (§III, Fig. 5)\n\n"
     << "Posture " << to_string(o.posture) << ", released with the feet "
     << fmt(1000 * clearance_m, 0) << " mm above the ground, " << fmt(o.duration_s, 1)
     << " s; touchdown at " << fmt(r.touchdown_s) << " s. Converged = the J3 torque stays within ±"
     << fmt(j["converge_band_nm"].get<double>(), 2) << " N·m (" << fmt(100 * o.converge_fraction, 0)
     << " % of max(|final|, " << fmt(o.converge_reference_nm, 1)
     << " N·m)) of its final value (mean of the last " << fmt(o.final_window_s, 2)
     << " s), counted from touchdown, after a " << fmt(1000 * o.cut_after_touchdown_s, 0)
     << " ms cut; slowest leg.\n\n"
     << "| quantity | motoflex | paper |\n|---|---|---|\n"
     << "| knee Fz, mean of 4 legs [N] | " << fmt(j["knee_fz_n"].get<double>(), 2)
     << " (model: " << fmt(r.expected_knee_fz_n, 2) << ") | 49.1 |\n"
     << "| largest other knee component: \\|Fx\\|, \\|Fy\\| [N] / \\|M\\| [N·m] | "
     << fmt(j["knee_other_force_max_n"].get<double>(), 3) << " / "
     << fmt(j["knee_other_moment_max_nm"].get<double>(), 3) << " | → 0 |\n"
     << "| final J3 torque FL, feedback / Jacobian [N·m] | " << fmt(r.knee_feedback_nm[0], 3)
     << " / " << fmt(r.knee_jacobian_nm[0], 3) << " | 0 |\n"
     << "| final J4 (ankle servo) torque FL [N·m] | " << fmt(r.ankle_feedback_nm[0], 3)
     << " | – |\n"
     << "| J3 converge time, feedback eq. 4–5 [s] | " << fmt(fb) << " | ≈ 2 |\n"
     << "| J3 converge time, Jacobian eq. 7 [s] | " << fmt(jac) << " | ≈ 5× faster |\n"
     << "| knee Fz converge time (5 % of Fz) [s] | " << fmt(max_leg(r.fz_converge_s))
     << " | fast (f1, f2 converge rapidly) |\n"
     << "| J3 landing peak, within the cut [N·m] | " << fmt(r.landing_peak_nm[0], 2)
     << " (J3 τ_max 25.7; sign conventions differ) | −25 |\n"
     << "| eq. 4 residual \\|f1 + f2\\|, max [N] | " << fmt_g(r.max_third_law_residual_n)
     << " | 0 |\n"
     << "| max \\|τ3 feedback − τ3 Jacobian − τ4 ankle\\| after the cut [N·m] | "
     << fmt(r.max_knee_gap_beyond_ankle_nm, 4) << " | – |\n\n"
     << "Why the feedback torque settles slowly here: ODE 0.16's dWorldStep returns the exact "
        "constraint forces of each step (the eq. 4 residual is "
     << fmt_g(r.max_third_law_residual_n)
     << " N), so the feedback has no latency of its own. The difference between the two "
        "derivations is the ankle: the shank carries the J4 servo's torque τ4 to the knee, "
        "which eq. 5 includes and eq. 7 (force at J4 only) leaves out; feedback − Jacobian "
        "equals τ4 to within "
     << fmt(r.max_knee_gap_beyond_ankle_nm, 4)
     << " N·m. After landing the low-gain ankle servo (k_d 1/s, τ_max 1 N·m, Table I) sits "
        "at its torque limit and then relaxes slowly, so t1, t2 of the feedback settle slowly "
        "while f1, f2 settle fast — the paper's observation, with this cause.\n\n"
     << "![Fig. 5 style](fig5_static_knee.png)\n\n";
}

void updown_section(std::ostream& md, const TitanUpDownStudyOptions& o, const TitanUpDownResult& r,
                    const nlohmann::ordered_json& j) {
  md << "## Up-and-down calibration (§VI)\n\n"
     << "Body height ±" << fmt(1000 * o.motion.amplitude_m, 0) << " mm, period "
     << fmt(o.motion.period_s, 1) << " s, posture " << to_string(o.motion.posture)
     << "; the rise is " << fmt(r.rise_start_s, 2) << "–" << fmt(r.rise_end_s, 2)
     << " s (bottom to top), the period integral from the same bottom to the next.\n\n"
     << "| quantity | motoflex | paper |\n|---|---|---|\n"
     << "| potential-energy gain over the rise [J] | " << fmt(r.potential_gain_j, 4) << " | – |\n"
     << "| ∫Σ τω dt over the rise, feedback, all servos [J] | " << fmt(r.integrated_power_j, 4)
     << " (" << fmt_g(j["rise_error_percent"].get<double>()) << " % off) | = gain |\n"
     << "| ∫Σ τω dt over the rise, J1–J3 feedback / Jacobian [J] | "
     << fmt(r.integrated_power_active_j, 4) << " / " << fmt(r.integrated_power_jacobian_j, 4)
     << " | – |\n"
     << "| kinetic-energy change over the rise [J] | " << fmt_g(r.kinetic_change_j) << " | 0 |\n"
     << "| ∫Σ τω dt over a whole period, feedback [J] | " << fmt_g(r.period_integral_j) << " ("
     << fmt_g(j["period_integral_percent_of_rise"].get<double>()) << " % of the rise) | 0 |\n"
     << "| same, Jacobian J1–J3 [J] | " << fmt_g(r.period_integral_jacobian_j) << " | – |\n\n"
     << "![up-and-down](updown.png)\n\n";
}

void crawl_section(std::ostream& md, const TitanPaperStudyPlan& plan,
                   const TitanPaperStudyResults& results) {
  md << "## Crawl, postures A–D (§V, Fig. 8–10)\n\n"
     << plan.crawl.periods << " periods of 4.8 s per posture. Averaged absolute power (eq. 8) "
     << "over 4 legs × J1–J3 in the parallel-link knee coordinates (eq. 1); torques from eq. 7 "
     << "(r_a, F at J4; the paper's method) and, for comparison, from the joint feedback "
     << "(eq. 4–5) and eq. 7 in serial coordinates. Exchange: " << to_string(plan.crawl.plot_leg)
     << " leg, " << fmt(plan.crawl.exchange_from_s, 1) << "–" << fmt(plan.crawl.exchange_to_s, 1)
     << " s of each cycle: work per cycle of J2 and J3 and the correlation of P2(t), P3(t).\n\n"
     << "| posture | eq. 8 [W] | J1 | J2 | J3 | feedback eq. 8 [W] | serial eq. 8 [W] | "
        "window W2 / W3 [J] | corr(P2,P3) | advance [m] | end |\n"
     << "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const TitanCrawlResult& c : results.crawls) {
    md << "| " << to_string(c.posture) << " | " << fmt(c.jacobian.total_w, 3) << " | "
       << fmt(c.jacobian.joint_w[0], 3) << " | " << fmt(c.jacobian.joint_w[1], 3) << " | "
       << fmt(c.jacobian.joint_w[2], 3) << " | " << fmt(c.feedback.total_w, 3) << " | "
       << fmt(c.jacobian_serial.total_w, 3) << " | " << fmt(c.exchange_work_j2_j, 3) << " / "
       << fmt(c.exchange_work_j3_j, 3) << " | " << fmt(c.exchange_power_correlation, 2) << " | "
       << fmt(c.advance_m, 3) << " | " << to_string(c.end) << " |\n";
  }
  md << "\nPaper (Fig. 10, values not in the text): A, the GDA posture, has the lowest averaged "
        "power, single-digit watts in ODE, below the hardware's; in B–D J2 and J3 exchange power "
        "(mirror-image curves) in 2.4–4.8 s.\n\n"
     << "![Fig. 8 style](fig8_torque.png)\n\n![Fig. 9 style](fig9_power.png)\n\n"
     << "![Fig. 10 style](fig10_power.png)\n\n";
}

}  // namespace

void write_titan_study_report(const TitanStudyConfig& config, const TitanPaperStudyResults& results,
                              const std::string& out_dir, bool plots) {
  std::filesystem::create_directories(out_dir);
  const nlohmann::ordered_json json = titan_study_json(config, results);
  const std::filesystem::path dir(out_dir);
  write_file_atomically((dir / "titan.json").string(), json.dump(2) + "\n");
  write_titan_study_series(config, results, out_dir);

  std::ostringstream md;
  md << "# TITAN-VIII torque/power study (seed 000)\n\n"
     << "Endo, Arikawa, Hirose, ICRA 2011, reproduced with `motoflex titan " << config.path
     << "`: ODE "
     << "0.16 dWorldStep, " << fmt(1000 * config.plan.setup.rollout.dt_s, 1) << " ms steps, servo `"
     << config.plan.setup.rollout.servo << "` (eq. 3, Table I), contacts mu "
     << config.plan.setup.parameters.get("contact.mu") << " with the friction pyramid, slip "
     << config.plan.setup.parameters.get("contact.slip") << ", soft ERP "
     << config.plan.setup.parameters.get("contact.soft_erp") << ", soft CFM "
     << config.plan.setup.parameters.get("contact.soft_cfm") << ". All numbers: `titan.json`.\n\n"
     << "Torque conventions: a joint torque is what the joint applies to its distal body about "
        "its axis (the actuator torque; power τ·ω > 0 when the actuator does work). Eq. 4–5 "
        "moves ODE's feedback (f1, t1 at the child's CoM) to the joint point; eq. 7 uses the "
        "force J4 transmits to the foot. Eq. 1: the parallel knee angle is the shank's absolute "
        "angle θ3p = θ2 + θ3, so τ2p = τ2 − τ3, τ3p = τ3, ω3p = ω2 + ω3 "
        "(include/motoflex/studies/titan/parallel_knee.hpp).\n\n";
  static_section(md, config.plan.stand, results.stand, json["static"],
                 config.plan.setup.model->initial_clearance_m);
  updown_section(md, config.plan.updown, results.updown, json["updown"]);
  crawl_section(md, config.plan, results);
  md << "## Speed (§II-A)\n\n";
  if (results.timing) {
    const TitanCrawlTiming& t = *results.timing;
    md << "A " << fmt(t.simulated_s, 1) << " s crawl (posture "
       << to_string(config.plan.timing_posture) << ", " << t.steps << " steps of dWorldStep) took "
       << fmt(t.wall_s, 2) << " s wall time in one thread with the torque probe, "
       << fmt(t.wall_bare_s, 2) << " s without: **" << fmt(t.wall_s * 10.0 / t.simulated_s, 2)
       << " s per 10 s of crawl** (fastest of " << t.wall_runs_s.size() << " runs:";
    for (const double w : t.wall_runs_s) md << " " << fmt(w, 2);
    md << " s; its thread CPU time " << fmt(t.cpu_s, 2)
       << " s; paper: 60 s on a 2011 Core2Quad 3 GHz).\n\n";
  } else {
    md << "No timing run (timing.crawl_s = 0).\n\n";
  }
  md << "Whole study: " << fmt(results.wall_s, 1) << " s wall time.\n";
  write_file_atomically((dir / "report.md").string(), md.str());

  if (plots) {
    run_plot_script("plot_titan.py", {out_dir, "--leg", to_string(config.plan.crawl.plot_leg)});
  }
}

}  // namespace motoflex
