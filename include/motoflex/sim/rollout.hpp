#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"
#include "motoflex/motion/command_trajectory.hpp"

namespace motoflex {

enum class StepSolver {
  kStep,        // dWorldStep: exact LCP (Dantzig); bit-reproducible whatever the thread count
  kSparseStep,  // dWorldStep with motoflex's LCP solver (src/sim/box_lcp.hpp): the same exact
                // LCP, solved by warm-started block pivoting on a sparse LDLᵀ, so the same
                // answer up to rounding in fewer operations; each rollout owns its solver, so
                // reproducible whatever the thread count
  kQuickStep,   // dWorldQuickStep: iterative and faster. It shuffles constraint rows with ODE's
                // random generator, which each thread owns a copy of; each rollout loads its own
                // seed (0 at the start, like a fresh process) around every step, so a quick
                // rollout is reproducible whatever the threads and parallel ones run side by
                // side (src/sim/ode_thread_random.cpp)
};

// How the bending joints of flexible links (seed 001 §3.3) carry their spring.
enum class FlexModel {
  // Spring and damper in one implicit motor row per axis (target −(ERP/h)·α, CFM of ODE's
  // spring-damper equivalence): stable at any step; flex.damping_nm_s_per_rad damps it.
  kImplicit,
  // The 2011 program's (motoflex_2011.md §2.9): an explicit torque −flex.spring_nm_per_rad·α
  // each step, plus a motor row with target 0 and FMax flex.friction_nm whose CFM is the world's,
  // i.e. a damper 1/world.cfm (276 N·m·s/rad at the original's 3.617e-3) capped at FMax.
  kExplicitCfm,
};

struct RolloutOptions {
  double dt_s = 0.001;  // physics step
  StepSolver solver = StepSolver::kStep;
  int quickstep_iterations = 20;  // dWorldQuickStep only
  double quickstep_w = 1.3;       // dWorldQuickStep's SOR over-relaxation (ODE's default 1.3)
  // The state of ODE's random generator when the first quick step starts (it shuffles the
  // constraint rows with it, ode_thread_random.cpp); 0 is a fresh process's. Each value is one
  // draw of the rows' order, which an unconverged quick step's answer depends on.
  std::uint32_t quickstep_seed = 0;
  FlexModel flex_model = FlexModel::kImplicit;
  // Round every body's stored state (position, orientation, velocities) to single precision
  // after each step, as the 2011 program's float build of ODE keeps it (motoflex_2011.md §1).
  bool float_state = false;
  // A cap on the contact points per foot shape and step, below each shape's own limit (box and
  // cylinder 4, capsule 2, sphere 1, mesh 8); the default caps nothing. ODE's box-plane
  // collider returns at most 4, so the 2011 program's 10 per pair (motoflex_2011.md §2.10)
  // changes nothing for box feet on the ground plane.
  int max_contacts_per_foot = 64;
  int gear_substeps = 100;  // gear sub-steps per physics step (motoflex servo)
  // Servo law of every actuator (servo_law.hpp registry); empty = each joint's own law as the
  // robot assigns it (actuator_servo_name).
  std::string servo = "ideal";
  double settle_s = 0.0;        // hold the first commanded pose this long before t = 0
  std::uint64_t seed = 1;       // sensor-noise stream
  bool stop_on_fall = true;     // end the rollout at the first fall
  bool record_torques = false;  // fill RolloutResult::joint_torque_nm
  bool hold_torso = false;      // the root body hangs fixed in the air, feet 0.1 m above the
                                // ground (excitation motions without ground contact)
};

enum class RolloutEnd {
  kCompleted,    // every frame simulated
  kFell,         // a non-foot body touched the ground, or the torso tilted or dropped too far
  kDiverged,     // non-finite state, absurd speeds, or an ODE error inside the step
  kModelError,   // the parameters cannot be simulated (e.g. unstable gear sub-step)
  kStoppedEarly  // the frame observer asked to stop (e.g. the fit's early termination)
};
const char* to_string(RolloutEnd end);

// What one rollout produced, sampled at the frames of the commanded trajectory.
struct RolloutResult {
  std::vector<std::string> joint_names;
  std::vector<double> time_s;           // frame times (same as the trajectory's)
  std::vector<double> commanded_rad;    // frame-major [frame * joints + joint]
  std::vector<double> measured_rad;     // simulated encoder readings, same layout
  std::vector<double> joint_torque_nm;  // actuator torque at each frame (if recorded)
  std::vector<double> imu_roll_rad;
  std::vector<double> imu_pitch_rad;
  std::vector<double> torso_position_m;  // x, y, z of the torso CoM per frame
  std::vector<double> foot_force_z_n;    // per frame, the vertical ground force on each foot
  std::size_t frames_requested = 0;
  std::size_t frames_completed = 0;  // T of the fitness: frames before the end or a fall
  RolloutEnd end = RolloutEnd::kCompleted;
  double end_time_s = 0.0;
  std::string end_detail;  // e.g. "LThigh touched the ground"
  std::size_t physics_steps = 0;
  std::size_t joints() const { return joint_names.size(); }
};

// One robot in its own ODE world, stepped by one thread. Owns every ODE object it creates.
// The model and parameters must outlive it. Construction throws ModelError when the
// parameters cannot be simulated (e.g. an unstable gear sub-step).
class Rollout {
 public:
  Rollout(const RobotModel& model, const ParameterSet& parameters, const RolloutOptions& options,
          const std::vector<double>& initial_pose_rad);
  ~Rollout();
  Rollout(const Rollout&) = delete;
  Rollout& operator=(const Rollout&) = delete;

  // Advances one physics step. `command_now_rad` is the commanded angle at the current time
  // (what the servos regulate to), `command_next_rad` the one at the end of the step (the ideal
  // servo's target). Returns false once the rollout has ended (fall or divergence).
  bool step(const double* command_now_rad, const double* command_next_rad);
  // The supply voltage the robot logged at this time (V; NaN: none), read by the laws that
  // have a supply input (ServoInput::logged_supply_v) from the next step on.
  void set_logged_supply_v(double supply_v);

  double time_s() const { return time_s_; }
  RolloutEnd end() const { return end_; }
  const std::string& end_detail() const { return end_detail_; }
  std::size_t joints() const;

  double joint_angle_rad(std::size_t actuator) const;     // true angle (ODE)
  double joint_rate_rad_s(std::size_t actuator) const;    // true rate (ODE)
  double encoder_rad(std::size_t actuator);               // simulated sensor reading
  double actuator_torque_nm(std::size_t actuator) const;  // torque the actuator applied last step
  void imu_roll_pitch(double& roll_rad, double& pitch_rad) const;
  Eigen::Vector3d torso_position_m() const;
  double torso_tilt_rad() const;
  // Foot force sensors: the ground's force on each foot box during the last step (world
  // frame, N; z is the load it carries), from the contact joints' feedback.
  std::size_t foot_count() const;
  Eigen::Vector3d foot_force_n(std::size_t foot) const;
  std::string foot_name(std::size_t foot) const;

  // Rigid-body state of model body `index` (ModelError for a static, welded body): CoM
  // position, orientation R_WB, linear and angular velocity (world frame), mass and inertia
  // about the CoM in the body frame.
  struct BodyState {
    Eigen::Vector3d position_m = Eigen::Vector3d::Zero();
    Eigen::Matrix3d R_WB = Eigen::Matrix3d::Identity();
    Eigen::Vector3d velocity_m_s = Eigen::Vector3d::Zero();
    Eigen::Vector3d angular_velocity_rad_s = Eigen::Vector3d::Zero();
    double mass_kg = 0.0;
    Eigen::Matrix3d inertia_B_kg_m2 = Eigen::Matrix3d::Zero();
  };
  // False for a static body (the welded base of a fixed-base robot).
  bool body_is_dynamic(std::size_t index) const;
  BodyState body_state(std::size_t index) const;
  Eigen::Vector3d gravity_m_s2() const;

  // Joint constraint forces (seed 000 eq. 4–5): after enable_joint_feedback(j), every step
  // records the force and torque model joint j applies to its body 1 (the child of a hinge:
  // Rollout's convention) and body 2 (the parent), at the bodies' CoMs, world frame.
  struct JointFeedback {
    Eigen::Vector3d force1_n = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque1_nm = Eigen::Vector3d::Zero();
    Eigen::Vector3d force2_n = Eigen::Vector3d::Zero();
    Eigen::Vector3d torque2_nm = Eigen::Vector3d::Zero();
  };
  void enable_joint_feedback(std::size_t joint);
  JointFeedback joint_feedback(std::size_t joint) const;
  // A hinge joint's current anchor (as attached to body 1) and unit axis, world frame.
  void hinge_frame(std::size_t joint, Eigen::Vector3d& anchor_m, Eigen::Vector3d& axis) const;

 private:
  friend struct RolloutOdeAccess;  // src/sim/rollout_ode_access.hpp: ODE handles for tests
  struct Impl;
  std::unique_ptr<Impl> impl_;
  double time_s_ = 0.0;
  RolloutEnd end_ = RolloutEnd::kCompleted;
  std::string end_detail_;
};

// Called after each frame is recorded (result.frames_completed == frame + 1); returning false
// stops the rollout with RolloutEnd::kStoppedEarly.
using FrameObserver = std::function<bool(const RolloutResult& result, std::size_t frame)>;

// Runs a whole rollout: settles on the first commanded pose, then follows the trajectory,
// sampling the encoders at every trajectory frame. Never throws for a rollout that fails: a
// ModelError or divergence is reported in the result.
RolloutResult run_rollout(const RobotModel& model, const ParameterSet& parameters,
                          const CommandTrajectory& commands, const RolloutOptions& options,
                          const FrameObserver& observer = {});

}  // namespace motoflex
