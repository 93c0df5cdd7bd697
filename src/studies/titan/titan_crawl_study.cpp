// Seed 000 §V: joint torque and power of the crawl in postures A–D (Fig. 8–10). Torques from
// eq. 7 (the paper's) and eq. 4–5, converted to the parallel-link knee of eq. 1, powers τ·ω,
// averaged absolute power of eq. 8 over n periods.

#include <cmath>
#include <stdexcept>

#include "motoflex/studies/titan/joint_energy.hpp"
#include "motoflex/studies/titan/parallel_knee.hpp"
#include "motoflex/studies/titan/titan_study.hpp"
#include "titan_study_run.hpp"

namespace motoflex {
namespace {

TitanPowerSummary summarise(const JointEnergyMeter& meter) {
  TitanPowerSummary summary;
  summary.total_w = meter.averaged_absolute_power_w();
  for (std::size_t l = 0; l < 4; ++l) {
    for (std::size_t j = 0; j < 3; ++j) {
      const double w = meter.averaged_absolute_power_w(l * 3 + j);
      summary.leg_joint_w[l][j] = w;
      summary.joint_w[j] += w;
    }
  }
  return summary;
}

// Pearson correlation from running sums.
struct Correlation {
  double n = 0, sx = 0, sy = 0, sxx = 0, syy = 0, sxy = 0;
  void add(double x, double y) {
    n += 1;
    sx += x;
    sy += y;
    sxx += x * x;
    syy += y * y;
    sxy += x * y;
  }
  double value() const {
    const double cov = sxy - sx * sy / n;
    const double vx = sxx - sx * sx / n, vy = syy - sy * sy / n;
    return vx > 0.0 && vy > 0.0 ? cov / std::sqrt(vx * vy) : 0.0;
  }
};

// What the crawl study accumulates step by step: energy meters of the three torque methods,
// the plotted leg's energy exchange between joints 2 and 3, and its last cycle's curves.
class CrawlObserver {
 public:
  CrawlObserver(const TitanCrawlStudyOptions& options, double period_s, double dt_s,
                TitanCrawlResult& result)
      : options_(options),
        period_s_(period_s),
        dt_s_(dt_s),
        plot_leg_(static_cast<std::size_t>(options.plot_leg)),
        result_(result) {}

  void observe(double t, const TitanTorqueProbe* probe) {
    if (first_) start_x_ = probe->rollout().torso_position_m().x();
    first_ = false;
    const double mid = t - 0.5 * dt_s_;  // this step covers (t − dt, t]
    const int cycle = static_cast<int>(std::floor(mid / period_s_));
    const double phase = t - cycle * period_s_;
    for (std::size_t l = 0; l < 4; ++l) observe_leg(l, probe->leg(kTitanLegs[l]), cycle, phase);
    jacobian_.advance(dt_s_);
    feedback_.advance(dt_s_);
    jacobian_serial_.advance(dt_s_);
    result_.advance_m = probe->rollout().torso_position_m().x() - start_x_;
  }

  // The energy summaries and exchange figures into the result.
  void finish() {
    result_.jacobian = summarise(jacobian_);
    result_.feedback = summarise(feedback_);
    result_.jacobian_serial = summarise(jacobian_serial_);
    const double cycles = options_.periods;
    const double window_s = (options_.exchange_to_s - options_.exchange_from_s) * cycles;
    result_.exchange_work_j2_j = exchange_work2_ / cycles;
    result_.exchange_work_j3_j = exchange_work3_ / cycles;
    result_.exchange_mean_abs_power_j2_w = exchange_abs2_ / window_s;
    result_.exchange_mean_abs_power_j3_w = exchange_abs3_ / window_s;
    result_.exchange_power_correlation = correlation_.value();
  }

 private:
  void observe_leg(std::size_t l, const TitanLegSample& s, int cycle, double phase) {
    const Eigen::Vector3d rate(s.rate_rad_s[0], s.rate_rad_s[1], s.rate_rad_s[2]);
    const Eigen::Vector3d tau_jac(s.jacobian_torque_nm[0], s.jacobian_torque_nm[1],
                                  s.jacobian_torque_nm[2]);
    const Eigen::Vector3d tau_fb(s.feedback_torque_nm[0], s.feedback_torque_nm[1],
                                 s.feedback_torque_nm[2]);
    // Seed 000 eq. 1: the hardware's parallel-link knee.
    const Eigen::Vector3d rate_p = parallel_knee_rates(rate);
    const Eigen::Vector3d tau_jac_p = parallel_knee_torques(tau_jac);
    const Eigen::Vector3d tau_fb_p = parallel_knee_torques(tau_fb);
    const Eigen::Vector3d power_jac = tau_jac_p.cwiseProduct(rate_p);
    const Eigen::Vector3d power_fb = tau_fb_p.cwiseProduct(rate_p);
    for (int j = 0; j < 3; ++j) {
      jacobian_.add(l * 3 + j, power_jac[j], dt_s_);
      feedback_.add(l * 3 + j, power_fb[j], dt_s_);
      jacobian_serial_.add(l * 3 + j, tau_jac[j] * rate[j], dt_s_);
    }
    if (l != plot_leg_) return;
    if (phase > options_.exchange_from_s && phase <= options_.exchange_to_s) {
      exchange_work2_ += power_jac[1] * dt_s_;
      exchange_work3_ += power_jac[2] * dt_s_;
      exchange_abs2_ += std::abs(power_jac[1]) * dt_s_;
      exchange_abs3_ += std::abs(power_jac[2]) * dt_s_;
      correlation_.add(power_jac[1], power_jac[2]);
    }
    if (cycle == options_.periods - 1) {
      result_.cycle_time_s.push_back(phase);
      for (int j = 0; j < 3; ++j) {
        result_.cycle_torque_nm[j].push_back(tau_jac_p[j]);
        result_.cycle_power_w[j].push_back(power_jac[j]);
        result_.cycle_feedback_torque_nm[j].push_back(tau_fb_p[j]);
        result_.cycle_feedback_power_w[j].push_back(power_fb[j]);
      }
    }
  }

  const TitanCrawlStudyOptions& options_;
  double period_s_, dt_s_;
  std::size_t plot_leg_;
  TitanCrawlResult& result_;
  JointEnergyMeter jacobian_{12}, feedback_{12}, jacobian_serial_{12};
  double exchange_work2_ = 0.0, exchange_work3_ = 0.0, exchange_abs2_ = 0.0, exchange_abs3_ = 0.0;
  Correlation correlation_;
  double start_x_ = 0.0;
  bool first_ = true;
};

}  // namespace

TitanCrawlResult run_titan_crawl(const TitanStudySetup& setup,
                                 const TitanCrawlStudyOptions& options) {
  detail::check_titan_study_setup(setup);
  if (!(options.settle_s >= 0.0)) throw std::invalid_argument("TITAN crawl study: bad settle_s");
  TitanCrawlOptions gait_options;
  gait_options.posture = options.posture;
  gait_options.periods = options.periods;
  const TitanCrawl gait(gait_options);  // throws for periods < 1
  const double T = gait_options.period_s;
  if (!(options.exchange_from_s >= 0.0 && options.exchange_from_s < options.exchange_to_s &&
        options.exchange_to_s <= T)) {
    throw std::invalid_argument("TITAN crawl study: exchange window must lie within one period");
  }
  const RobotModel& model = *setup.model;
  const TitanKinematics kinematics(model);
  const CommandTrajectory commands = detail::titan_study_commands(setup, kinematics, gait);

  TitanCrawlResult result;
  result.posture = options.posture;
  result.duration_s = gait.duration_s();
  CrawlObserver observer(options, T, setup.rollout.dt_s, result);
  const auto observe = [&](double t, const TitanTorqueProbe* probe) { observer.observe(t, probe); };
  const detail::ProbeRunEnd end = detail::run_titan_probe_rollout(
      setup, kinematics, commands, options.settle_s, gait.duration_s(), true, observe);
  result.end = end.end;
  result.end_detail = end.detail;
  result.wall_s = end.wall_s;
  observer.finish();
  return result;
}

}  // namespace motoflex
