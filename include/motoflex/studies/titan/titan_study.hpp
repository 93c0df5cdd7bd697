#pragma once

#include <array>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/titan_gait.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {

// The TITAN-VIII torque/power study of seed 000 (Endo, Arikawa, Hirose, ICRA 2011): static
// standing (§III), the up-and-down calibration motion (§VI) and the crawl in postures A–D (§V).
// Every study simulates one rollout with a TitanTorqueProbe and derives joint torques two ways:
// "feedback" (eq. 4–5, ODE's 6-axis joint feedback) and "jacobian" (eq. 7, the J4 force through
// the leg Jacobian, the paper's choice for walking). Powers are τ·ω; the crawl's are taken in the
// parallel-link knee coordinates of eq. 1 (parallel_knee.hpp), like the hardware's.

// What every study shares: the robot, its parameters (contact, servo gains), how it is stepped.
struct TitanStudySetup {
  // The model's default parameters and rollout options; `model` must not be null.
  explicit TitanStudySetup(std::shared_ptr<const RobotModel> robot)
      : model(std::move(robot)), parameters(model->parameters) {}

  std::shared_ptr<const RobotModel> model;  // TITAN-VIII-like (TitanKinematics checks)
  ParameterSet parameters;
  RolloutOptions rollout;  // servo must drive ODE motor rows (velocity or ideal); settle_s unused
  bool servo_lead = true;  // commands carry θ̇_plan / k_d (titan_gait.hpp); velocity servo only
  double command_rate_hz = 100.0;  // frame rate of the commanded trajectories
};

// ---- §III static standing ----

struct TitanStaticOptions {
  TitanPosture posture = TitanPosture::kA;
  double duration_s = 5.0;              // from release (feet 10 mm above the ground) on
  double cut_after_touchdown_s = 0.03;  // §III-A: the landing impulse is cut away
  double converge_fraction = 0.05;      // §III-A: 5 % tolerance ...
  // ... of max(|final value|, this) [N·m]. The knee torque's final value is ≈ 0 in posture A, so
  // the band is 5 % of the paper's J3 operating range of about 10 N·m (§III-A, Fig. 8).
  double converge_reference_nm = 10.0;
  double final_window_s = 0.5;  // the final value is the mean over the last this-many seconds
};

struct TitanStaticResult {
  RolloutEnd end = RolloutEnd::kCompleted;
  std::string end_detail;
  double touchdown_s = 0.0;         // first foot contact after release
  double expected_knee_fz_n = 0.0;  // (total mass − shanks and feet)·g / 4 (footnote 2)
  // Final values per leg (TitanLeg order): knee load (paper's sign) and J3 torque both ways.
  std::array<Eigen::Vector3d, 4> knee_force_n{};
  std::array<Eigen::Vector3d, 4> knee_moment_nm{};
  std::array<double, 4> knee_feedback_nm{};
  std::array<double, 4> knee_jacobian_nm{};
  std::array<double, 4> ankle_feedback_nm{};  // the J4 servo torque the shank also carries
  // Time from touchdown until the J3 torque stays within the band of its final value [s].
  std::array<double, 4> feedback_converge_s{};
  std::array<double, 4> jacobian_converge_s{};
  std::array<double, 4> fz_converge_s{};  // knee Fz within converge_fraction of its final value
  // J3 feedback torque of largest magnitude within the cut after touchdown (the landing
  // impulse; the paper: −25 N·m) [N·m], per leg.
  std::array<double, 4> landing_peak_nm{};
  double max_third_law_residual_n = 0.0;  // eq. 4 check, whole run
  // Why the two derivations differ: eq. 7 sees only the force at J4, while the shank also
  // carries the ankle servo's torque τ4 to the knee. Largest |τ3_feedback − τ3_jacobian − τ4|
  // after the cut, over the legs [N·m] (what the ankle torque leaves unexplained: the shank's
  // own weight and inertia).
  double max_knee_gap_beyond_ankle_nm = 0.0;
  // Series at every physics step (time since release, after the step).
  std::vector<double> time_s;
  std::array<std::vector<double>, 4> knee_feedback_series_nm;
  std::array<std::vector<double>, 4> knee_jacobian_series_nm;
  std::array<std::vector<double>, 4> knee_fz_series_n;
  std::array<std::vector<double>, 4> ankle_feedback_series_nm;  // J4 torque, eq. 4–5
};

// Throws std::invalid_argument for invalid options or a robot TitanKinematics rejects.
TitanStaticResult run_titan_static(const TitanStudySetup& setup, const TitanStaticOptions& options);

// ---- §VI sinusoidal up-and-down ----

struct TitanUpDownStudyOptions {
  TitanUpDownOptions motion;  // periods >= 2: the rise and the period are taken in the second
  double settle_s = 0.5;      // land and settle on the first pose before the motion starts
};

struct TitanUpDownResult {
  RolloutEnd end = RolloutEnd::kCompleted;
  std::string end_detail;
  double rise_start_s = 0.0;      // a bottom of the planned motion (motion time)
  double rise_end_s = 0.0;        // the following top
  double potential_gain_j = 0.0;  // Σ m g Δh of all bodies over the rise (simulated)
  double kinetic_change_j = 0.0;  // over the rise (≈ 0: the body rests at bottom and top)
  // ∫ Σ τ·ω dt over the rise, all 16 servos, feedback torques (eq. 4–5): the true joint work.
  double integrated_power_j = 0.0;
  double integrated_power_active_j = 0.0;    // J1–J3 only
  double integrated_power_jacobian_j = 0.0;  // J1–J3 with eq. 7 torques (leg masses neglected)
  // ∫ Σ τ·ω dt from the bottom over one whole period (feedback; back to the same height).
  double period_integral_j = 0.0;
  double period_integral_jacobian_j = 0.0;
  // Series at the end of every physics step of the motion (motion time).
  std::vector<double> time_s;
  std::vector<double> body_height_m;
  std::vector<double> potential_j;
  std::vector<double> work_feedback_j;  // cumulative ∫ Σ τ·ω dt since the motion start, all servos
  std::vector<double> work_jacobian_j;  // cumulative, J1–J3, eq. 7
};

TitanUpDownResult run_titan_updown(const TitanStudySetup& setup,
                                   const TitanUpDownStudyOptions& options);

// ---- §V crawl ----

struct TitanCrawlStudyOptions {
  TitanPosture posture = TitanPosture::kA;
  int periods = 3;        // §V-B: averaged over 3 periods
  double settle_s = 0.5;  // land and settle on the first pose before the gait starts
  TitanLeg plot_leg = TitanLeg::kFL;
  // Window of every plot-leg cycle where §V-A compares J2 and J3 power [s, in the cycle].
  double exchange_from_s = 2.4;
  double exchange_to_s = 4.8;
};

// Averaged absolute powers (eq. 8) of one torque derivation [W].
struct TitanPowerSummary {
  double total_w = 0.0;                                // Σ over 4 legs and J1–J3
  std::array<double, 3> joint_w{};                     // per joint J1, J2, J3, summed over the legs
  std::array<std::array<double, 3>, 4> leg_joint_w{};  // [leg][joint]
};

struct TitanCrawlResult {
  TitanPosture posture = TitanPosture::kA;
  RolloutEnd end = RolloutEnd::kCompleted;
  std::string end_detail;
  double duration_s = 0.0;  // n T
  double advance_m = 0.0;   // torso travel along x over the gait
  // Eq. 8 over the n periods, J1–J3 of all legs, parallel-link coordinates (eq. 1):
  TitanPowerSummary jacobian;         // eq. 7 torques: the paper's method
  TitanPowerSummary feedback;         // eq. 4–5 torques
  TitanPowerSummary jacobian_serial;  // eq. 7 torques in the model's serial coordinates
  // Plot leg, exchange window of every cycle (eq. 7, parallel): ∫P dt per cycle, mean over the
  // cycles [J], and the correlation of P2(t) with P3(t) over the windows (−1: mirror images).
  double exchange_work_j2_j = 0.0;
  double exchange_work_j3_j = 0.0;
  double exchange_mean_abs_power_j2_w = 0.0;
  double exchange_mean_abs_power_j3_w = 0.0;
  double exchange_power_correlation = 0.0;
  // Plot leg over its last complete cycle, every physics step (time within the cycle):
  std::vector<double> cycle_time_s;
  std::array<std::vector<double>, 3> cycle_torque_nm;           // eq. 7, parallel
  std::array<std::vector<double>, 3> cycle_power_w;             // eq. 7, parallel
  std::array<std::vector<double>, 3> cycle_feedback_torque_nm;  // eq. 4–5, parallel
  std::array<std::vector<double>, 3> cycle_feedback_power_w;
  double wall_s = 0.0;  // wall time of the gait's stepping (settle excluded)
};

TitanCrawlResult run_titan_crawl(const TitanStudySetup& setup,
                                 const TitanCrawlStudyOptions& options);

// ---- speed ----

struct TitanCrawlTiming {
  double simulated_s = 0.0;
  double wall_s = 0.0;              // stepping with the torque probe (feedback on): the best run
  std::vector<double> wall_runs_s;  // every run with the probe
  double cpu_s = 0.0;  // thread CPU time of the fastest run (what the machine's load cannot add)
  double wall_bare_s = 0.0;  // the same crawl without the probe (one run)
  std::size_t steps = 0;
};

// Wall time of `simulated_s` of crawl in `posture` (after a 0.5 s settle that is not timed), in
// the calling thread: `repeats` runs with the torque probe (the fastest is reported, the others
// show how much a loaded machine disturbs it) and one without. Throws std::invalid_argument
// unless simulated_s > 0 and repeats >= 1.
TitanCrawlTiming time_titan_crawl(const TitanStudySetup& setup, TitanPosture posture,
                                  double simulated_s, int repeats = 1);

}  // namespace motoflex
