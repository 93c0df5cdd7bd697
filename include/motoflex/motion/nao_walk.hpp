#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"
#include "motoflex/motion/nao_leg_kinematics.hpp"

namespace motoflex {

// Straight walking of a Nao-class robot, generated open loop like the Czarnetzki et al. walk
// the MoToFlex paper used: footsteps → reference ZMP → CoM by ZMP preview control on the
// cart-table model → leg inverse kinematics.
//
// Timing convention: `step_duration_s` is one gait cycle (a left and a right step), as in that
// walk (the Dortmund walking engine in the Nao Devils code release splits its stepDuration into
// the phases of two steps and sets the step length to speed · stepDuration / 2). Each step takes
// half of it and moves the swing foot `step_length = speed · step_duration_s / 2` ahead of the
// support foot; each foot advances speed · step_duration_s per cycle. Read per step instead,
// seed 001's and issue 3's 200 mm/s at 2 s would be 0.4 m steps, twice the leg (0.203 m).
//
// Reach (rigid Nao, CoM 0.24 m: hips 0.205 m and ankles 0.045 m above the ground): with flat
// feet and an upright torso a rear foot can trail the hip by at most 0.120 m (HipPitch <= 0.484
// rad), a front foot lead it by 0.124 m (leg length). The swing foot lifts off about a step
// length minus the ZMP's heel-to-toe roll behind the CoM, which in a long single support stays
// close above the support foot: flat feet reach 0.137 m steps at step_duration_s 1 (274 mm/s)
// but only 0.110 m at 2 (110 mm/s). Toe-off and heel strike let the feet roll over their edges
// (a 0.6 rad heel lift alone lets the rear foot trail 0.065 m farther); with toe_off_rad 0.8,
// heel_strike_rad 0.6 and double_support_ratio 0.4 the steps reach 0.208 m at 2 s (208 mm/s)
// and 0.168 m at 1 s (337 mm/s). Beyond that plan_nao_walk names the limit.
struct NaoWalkParams {
  double speed_mm_s = 100.0;          // forward speed while walking
  double step_duration_s = 1.0;       // one gait cycle (two steps)
  double step_height_m = 0.02;        // swing-foot lift
  double double_support_ratio = 0.2;  // share of each step with both feet down
  // Whole-body CoM above the ground (constant). Standing straight the Nao's CoM is 0.271 m up;
  // 0.24 bends the knees enough for 0.137 m steps at 1 s per cycle (see the reach above).
  double com_height_m = 0.24;
  double foot_spacing_m = 0.10;  // lateral distance between the two ankles
  double start_s = 1.0;          // standing before the first step; the weight shift ends it
  double stop_s = 1.0;           // after the closing step: weight back to the middle, rest
  double duration_s = 10.0;      // whole motion; the steps fill duration − start − stop
  double rate_hz = 100.0;        // command (log) rate; also the preview control period
  // Reference ZMP inside the support foot, relative to the ankle: x forward, y toward the
  // other foot (inward). The sole spans x ∈ [−0.05, 0.10] m around the ankle.
  double zmp_offset_x_m = 0.015;
  double zmp_offset_y_m = 0.02;  // less sideways sway: the hip and ankle rolls stay in range
  // During single support the reference ZMP rolls forward by this much (centred on the offset
  // above; capped at the step length; not in the first and the closing step).
  double zmp_travel_x_m = 0.04;
  // Shape of the reference ZMP's move from one foot to the other in each double support (and
  // of the start and stop transfers): 0 moves it at constant speed, so it starts and stops with
  // a jump in velocity, and the support torques change abruptly at the phase changes (the
  // sudden change Aldebaran blames for the Nao's sideways problem, seed 001 §5); 1 moves it
  // along a quintic smoothstep (zero velocity and acceleration at both ends); in between blends
  // the two. The same path, only the timing along it changes. Toe-off waits until the ZMP has
  // passed the rear toe edge, which comes later on a smoothstep: long steps reach less (200 mm/s
  // at 2 s with toe-off and heel strike plans up to 197 mm/s at 0.5, 191 mm/s at 1).
  double zmp_transfer_smoothing = 0.0;
  // Torso shifted forward of the CoM the mass model asks for (compensates what the cart-table
  // model leaves out).
  double torso_offset_x_m = 0.0;
  // Toe-off: in the double support the rear foot's heel rises about its toe edge, once the
  // reference ZMP has passed that edge, to this pitch at lift-off; the swing then turns the foot
  // toes-up for the heel strike. 0 keeps the feet flat (the walks of reference_data/). Only long
  // steps move the ZMP past the rear toe edge; shorter ones get a smaller lift or none (the
  // full angle needs 0.25 s of double support after the ZMP passed the edge). Walks with toe-off
  // also end with a half step before the closing step, as they start with one.
  double toe_off_rad = 0.0;
  // Heel strike: the swing foot lands on its heel edge with the toes up by this angle and rolls
  // flat about it in the double support before the ZMP reaches its heel (the same rules as
  // toe-off). 0 lands flat.
  double heel_strike_rad = 0.0;
  double preview_s = 1.6;  // look-ahead of the ZMP preview controller (weights: nao_walk.cpp)
  bool first_swing_left = false;  // the right foot steps first
  // Which joint limits the plan keeps to (scenario key `joint_limits: urdf | stops`): the URDF's
  // (the real Nao's ranges) or only those the simulated robot has as stops. The 2011 MoToFlex
  // box robot has none, like the original program, whose own 50 mm/s command file asks for
  // AnkleRoll 0.46 rad, beyond the Nao's 0.398: with `stops` a walk planned for it may do so too.
  NaoJointLimits joint_limits = NaoJointLimits::kUrdf;

  // The numeric options by their scenario key (speed_mm_s, step_duration_s, ...; every double
  // above), for the scenario reader and option searches.
  std::vector<std::pair<const char*, double*>> numeric_fields();
  // The value of numeric option `key`; nullopt for an unknown key.
  std::optional<double> numeric(std::string_view key) const;

  // Empty when the numbers are usable on their own (signs, ranges, time budget); otherwise one
  // line naming the parameter, its value and the limit. Reachability is checked by the planner.
  std::string validate() const;
};

enum class NaoSupport { kDouble, kLeft, kRight };

// One command frame of the plan. World frame: x forward, y left, z up; origin on the ground
// midway between the ankles at the start.
struct NaoWalkSample {
  double time_s = 0.0;
  NaoSupport support = NaoSupport::kDouble;
  Eigen::Vector2d zmp_ref_m = Eigen::Vector2d::Zero();  // reference ZMP
  Eigen::Vector2d zmp_m = Eigen::Vector2d::Zero();      // cart-table ZMP of the planned CoM
  Eigen::Vector2d com_m = Eigen::Vector2d::Zero();      // planned CoM (height com_height_m)
  Eigen::Vector2d com_accel_m_s2 = Eigen::Vector2d::Zero();
  Eigen::Vector3d left_sole_m = Eigen::Vector3d::Zero();  // sole points
  Eigen::Vector3d right_sole_m = Eigen::Vector3d::Zero();
  // The feet as given to the leg IK: flat (pitch 0, edge = sole point) or pitched about the toe
  // or heel edge (toe-off, heel strike, swing), with the yaw the hip-yaw-less leg gives them.
  NaoEdgeFoot left_foot, right_foot;
  double left_yaw_rad = 0.0, right_yaw_rad = 0.0;
  Eigen::Vector3d torso_m = Eigen::Vector3d::Zero();  // torso frame origin
};

struct NaoWalkPlan {
  NaoWalkParams params;
  double step_length_m = 0.0;  // swing foot lands this far ahead of the support foot
  int steps = 0;               // including the half and the closing steps
  double walk_start_s = 0.0;   // the first step begins (= start_s)
  double walk_end_s = 0.0;     // closing step done
  // Steady walking: from the end of the first full step (the CoM starts up over the half step
  // and that one) to the start of the closing step (or of the half step before it, with
  // toe-off) the CoM moves at the commanded speed on average.
  double steady_start_s = 0.0;
  double steady_end_s = 0.0;
  double mass_kg = 0.0;
  std::vector<NaoWalkSample> samples;  // one per command frame
  CommandTrajectory commands;          // model actuator order
};

// Plans the walk for `model` (a Nao: the ten leg actuators LHipRoll … RAnkleRoll; others are
// held at the stand pose). Throws std::invalid_argument naming the parameter and the limit
// when the parameters are invalid or not reachable. A walk the legs cannot follow is reported
// against speed_mm_s with the fastest speed that can be planned (bisection, 1 mm/s) and where
// the first leg failed, e.g.
//   "speed_mm_s = 400: step length 0.200 m (speed * step_duration_s / 2) exceeds the reachable
//    0.137 m (speed_mm_s <= 274) at com_height_m 0.24, step_duration_s 1; at t = 1.90 s: left
//    leg: hip-to-ankle distance 0.2047 m exceeds the leg length 0.2029 m (thigh + tibia); the
//    feet stay flat: toe_off_rad and heel_strike_rad let them roll over their toe and heel
//    edges for longer steps"
// and, when not even stepping in place works, against com_height_m.
NaoWalkPlan plan_nao_walk(const RobotModel& model, const NaoWalkParams& params);

// plan_nao_walk(...).commands.
CommandTrajectory nao_walk_trajectory(const RobotModel& model, const NaoWalkParams& params);

// The largest speed_mm_s (1 mm/s resolution, found by bisection on [0, 1000]) for which the walk
// with the other parameters of `params` can be planned; 0 if not even stepping in place can.
// Throws like plan_nao_walk for invalid parameters or an unreachable standing posture.
double nao_max_walk_speed_mm_s(const RobotModel& model, const NaoWalkParams& params);

}  // namespace motoflex
