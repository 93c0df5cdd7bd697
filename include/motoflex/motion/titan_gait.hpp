#pragma once

#include <Eigen/Core>
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/motion/titan_leg_kinematics.hpp"

namespace motoflex {

// Planned sole trajectories of TITAN-VIII (seed 000 §IV-B and §VI), in the body frame of
// titan_leg_kinematics.hpp (x forward, y left, z up, origin in the plane of the hip joints).
//
// Walking postures. The paper defines a posture by the FL foot's X, Y (the other feet mirrored)
// with Z = −0.243 m, but its Fig. 7 with the values is not available. Here (X, Y) is the FL
// foot's stroke centre: the standing position, from which each stance stroke runs ±0.09 m
// forward and back. A is the model's standard posture (README: thigh horizontal and shank
// vertical at the stroke centre, the GDA posture). B, C and D each move the stroke centre 0.06 m
// away from A, so that the shank is no longer vertical and the vertical load loads J3 as well as
// J2 (the paper's §V-A: J2 and J3 then exchange power):
//   A  X = 0.25, Y = 0.4028  standard, GDA: shank vertical at the stroke centre
//   B  X = 0.25, Y = 0.3428  feet 0.06 m inward: the shank leans inward (knee outside the foot)
//   C  X = 0.25, Y = 0.4628  feet 0.06 m outward: the shank leans outward (foot outside the knee)
//   D  X = 0.31, Y = 0.4028  feet 0.06 m forward (hind feet backward): the stroke runs more along
//                            the leg, so the shank sweeps from vertical to strongly outward
// Every posture stays within 90 % of the leg's reach and inside the joint limits over the whole
// stroke including the swing (tested).
enum class TitanPosture { kA, kB, kC, kD };
std::optional<TitanPosture> parse_titan_posture(std::string_view text);  // "A" … "D"
const char* to_string(TitanPosture posture);

struct TitanPostureSpec {
  double foot_x_m = 0.0;  // FL stroke centre, forward of the body centre
  double foot_y_m = 0.0;  // FL stroke centre, left of the body centre
};
TitanPostureSpec titan_posture(TitanPosture posture);

enum class TitanLegPhase { kStance, kSwing };

// Where the four soles should be over time. Positions are body-frame sole centres [m].
class TitanFootPlan {
 public:
  virtual ~TitanFootPlan() = default;
  virtual double duration_s() const = 0;
  virtual Eigen::Vector3d sole_position_m(TitanLeg leg, double t_s) const = 0;
  virtual TitanLegPhase phase(TitanLeg leg, double t_s) const = 0;
  // Height of the body origin above the stance soles at t_s [m] (0.243 in posture A).
  virtual double body_height_m(double t_s) const = 0;
  virtual std::string description() const = 0;
};

struct TitanCommandOptions {
  double rate_hz = 100.0;  // frame rate of the commanded trajectory
  // Velocity-servo gains k_d [1/s] per actuator (model order) whose lag the commands cancel;
  // empty: command the planned angles themselves. With eq. 3 of seed 000,
  // θ̇ = k_d (θ_cmd − θ), a joint commanded with the plan lags it by 1/k_d (0.25 s for Table I's
  // k_d = 4/s): the crawl's swing then peaks at 37 mm instead of 50 mm and lands 0.3–0.5 s late,
  // while the next leg already lifts, so for a moment only the two diagonal feet carry the
  // robot. Commanding θ_cmd = θ_plan + θ̇_plan / k_d makes the error obey ė = −k_d e, so the joint
  // follows the plan exactly once the start-up transient has died out (as long as τ_max is not
  // reached); J4's command is then −(J2 + J3) of the plan plus its own lead.
  std::vector<double> lead_gain_per_s;
};

// Commanded joint angles from t = 0 to plan.duration_s() at options.rate_hz (frames at k / rate,
// the last frame on the end), in model actuator order, every sole parallel to the body
// (J4 = −(J2 + J3) in the plan). Throws TitanUnreachable for a sole target the legs cannot
// reach, std::invalid_argument for a non-positive rate or lead gains of the wrong count or not
// positive.
CommandTrajectory titan_command_trajectory(const TitanKinematics& kinematics,
                                           const TitanFootPlan& plan,
                                           const TitanCommandOptions& options = {});

// The velocity servo's k_d of every actuator (`joint.<name>.gain_per_s`, model order), for
// TitanCommandOptions::lead_gain_per_s. Throws std::out_of_range naming a missing parameter.
std::vector<double> velocity_servo_gains_per_s(const RobotModel& model,
                                               const ParameterSet& parameters);

struct TitanCrawlOptions {
  TitanPosture posture = TitanPosture::kA;  // stroke centre of the FL foot
  double sole_z_m = -0.243;      // stance sole height in the body frame (paper: constant)
  double stroke_m = 0.18;        // stance stroke (paper §IV-B)
  double swing_height_m = 0.05;  // cycloid apex above the stance height (paper §IV-B)
  double period_s = 4.8;         // gait cycle (paper §IV-B)
  double duty_factor = 0.75;     // stance fraction of the cycle; one swing at a time needs ≥ 0.75
  int periods = 1;               // gait cycles in the plan
  // Empty when valid; otherwise why not.
  std::string invalid_reason() const;
};

// The crawl gait of §IV-B. Each stance foot moves straight backward relative to the body, at
// constant height, by stroke_m over duty·period (so the body walks forward at
// stroke / (duty·period) = 0.05 m/s); each swing is a cycloid forward by stroke_m over
// (1 − duty)·period, rising to swing_height_m, with zero velocity at lift-off and touch-down.
//
// Leg order (the classic crawl, left hind → left fore → right hind → right fore): FL swings
// during [0, 1.2) s of every cycle, then HR [1.2, 2.4), FR [2.4, 3.6), HL [3.6, 4.8) (for the
// paper's numbers; in general swing k starts at k·period/4). FL swinging first matches the
// paper's Fig. 8/9, which plot one FL cycle with the swing in its first 1.2 s. After a fore leg
// the diagonal hind leg swings, after a hind leg the fore leg on its side; with this order the
// body centre stays inside the support triangle of the three stance feet (on its edge at the
// switch instants when duty = 0.75 exactly, the limit of a statically stable crawl).
//
// At t = 0 every foot is on the ground where its phase puts it (FL at the rear end of its
// stroke, about to lift), so the robot starts in the steady gait; use a settle time to land it.
class TitanCrawl : public TitanFootPlan {
 public:
  // Throws std::invalid_argument with invalid_reason() for invalid options.
  explicit TitanCrawl(const TitanCrawlOptions& options);

  const TitanCrawlOptions& options() const { return options_; }
  double duration_s() const override { return options_.periods * options_.period_s; }
  Eigen::Vector3d sole_position_m(TitanLeg leg, double t_s) const override;
  TitanLegPhase phase(TitanLeg leg, double t_s) const override;
  double body_height_m(double) const override { return -options_.sole_z_m; }
  std::string description() const override;

  double swing_duration_s() const { return (1.0 - options_.duty_factor) * options_.period_s; }
  double stance_duration_s() const { return options_.duty_factor * options_.period_s; }
  // Start of the leg's swing within each cycle [s].
  double swing_start_s(TitanLeg leg) const;
  // Planned walking speed of the body over the ground [m/s].
  double body_speed_m_s() const { return options_.stroke_m / stance_duration_s(); }
  // The leg's stroke centre (the posture's foot position, mirrored for the other legs).
  Eigen::Vector3d stroke_centre_m(TitanLeg leg) const;

 private:
  TitanCrawlOptions options_;
};

struct TitanUpDownOptions {
  TitanPosture posture = TitanPosture::kA;  // where the feet stand
  double mean_sole_z_m = -0.243;            // sole height at the middle of the motion
  double amplitude_m = 0.03;                // the body rises and falls by ± this
  double period_s = 4.0;
  int periods = 1;
  std::string invalid_reason() const;
};

// The sinusoidal up-and-down motion of §VI: all four feet stay where they stand and the body
// rises and falls, body_height(t) = −mean_sole_z + amplitude·sin(2πt/period); it starts and
// ends at the mean height, moving up.
class TitanUpDown : public TitanFootPlan {
 public:
  explicit TitanUpDown(const TitanUpDownOptions& options);  // throws std::invalid_argument

  const TitanUpDownOptions& options() const { return options_; }
  double duration_s() const override { return options_.periods * options_.period_s; }
  Eigen::Vector3d sole_position_m(TitanLeg leg, double t_s) const override;
  TitanLegPhase phase(TitanLeg, double) const override { return TitanLegPhase::kStance; }
  double body_height_m(double t_s) const override;
  std::string description() const override;

 private:
  TitanUpDownOptions options_;
};

// Static standing: the soles held at a posture's stroke centres, Z = sole_z_m.
class TitanStand : public TitanFootPlan {
 public:
  // Throws std::invalid_argument unless duration_s > 0.
  TitanStand(TitanPosture posture, double duration_s, double sole_z_m = -0.243);

  double duration_s() const override { return duration_s_; }
  Eigen::Vector3d sole_position_m(TitanLeg leg, double t_s) const override;
  TitanLegPhase phase(TitanLeg, double) const override { return TitanLegPhase::kStance; }
  double body_height_m(double) const override { return -sole_z_m_; }
  std::string description() const override;

 private:
  TitanPosture posture_;
  double duration_s_;
  double sole_z_m_;
};

// A posture's stroke centre for one leg: (±X, ±Y, z) with the signs of the leg's quadrant.
Eigen::Vector3d titan_stroke_centre_m(TitanPosture posture, TitanLeg leg, double sole_z_m);

}  // namespace motoflex
