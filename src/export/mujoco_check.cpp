#include "motoflex/export/mujoco_check.hpp"

#include <chrono>
#include <cmath>

#include "motoflex/core/error.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/export/exported_file.hpp"
#include "motoflex/export/mjcf_export.hpp"
#include "motoflex/export/servo_export.hpp"
#include "motoflex/sim/rollout.hpp"
#include "mujoco_model.hpp"

namespace motoflex {
namespace {

// RolloutOptions::hold_torso: "feet 0.1 m above the ground".
constexpr double kHeldTorsoClearance_m = 0.1;

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// The commanded angles motoflex's servos receive at each physics step, as run_rollout samples
// them: settling steps on the first frame, then the trajectory at t (now) and t + dt (next).
struct CommandSamples {
  std::size_t settle_steps = 0;
  std::size_t steps = 0;          // after settling
  std::vector<double> now, next;  // [step * joints + joint]
};

CommandSamples sample_commands(const CommandTrajectory& commands, double dt_s, double settle_s) {
  CommandSamples out;
  const std::size_t n = commands.joints();
  out.settle_steps = static_cast<std::size_t>(std::llround(settle_s / dt_s));
  out.steps = static_cast<std::size_t>(std::floor(commands.duration_s() / dt_s + 1e-9));
  out.now.resize(out.steps * n);
  out.next.resize(out.steps * n);
  std::size_t hint_now = 0, hint_next = 0;
  for (std::size_t k = 0; k < out.steps; ++k) {
    const double t = commands.start_s() + k * dt_s;
    commands.sample(t, &out.now[k * n], hint_now);
    commands.sample(t + dt_s, &out.next[k * n], hint_next);
  }
  return out;
}

// One engine's replay of the sampled commands: angles per step (row-major, step × joint).
struct Replay {
  std::vector<double> angles_rad;
  std::size_t steps = 0;  // steps completed
  double seconds = 0.0;   // wall time of the replay (not of the settling)
  std::string end;        // how the motoflex rollout ended
  std::size_t geoms = 0, visual_geoms = 0;
};

// RMS in degrees of the angle difference of two replays over the steps both completed.
double rms_deg_between(const Replay& a, const Replay& b, std::size_t joints) {
  const std::size_t steps = std::min(a.steps, b.steps);
  if (steps == 0 || joints == 0) return 0.0;
  double total = 0.0;
  for (std::size_t k = 0; k < steps * joints; ++k) {
    const double e = (a.angles_rad[k] - b.angles_rad[k]) * (180.0 / M_PI);
    total += e * e;
  }
  return std::sqrt(total / static_cast<double>(steps * joints));
}

// `offsets_rad`: each joint's mounting offset. MuJoCo's qpos is the encoder's reading (the
// joint's `ref` is the offset), so motoflex's joint angles are compared with the offset added,
// and the robot is placed where its encoders read `first`.
Replay replay_in_motoflex(const ExportInput& input, const CommandSamples& samples,
                          const std::vector<double>& first, const std::vector<double>& offsets_rad,
                          const MujocoCheckOptions& options, StepSolver solver) {
  const std::size_t n = input.model.actuators.size();
  RolloutOptions rollout_options;
  rollout_options.dt_s = input.dt_s;
  rollout_options.solver = solver;
  rollout_options.servo = input.servo;
  rollout_options.gear_substeps = options.gear_substeps;
  rollout_options.hold_torso = options.hold_torso;
  rollout_options.stop_on_fall = false;
  Rollout rollout(input.model, input.parameters, rollout_options, first);
  for (std::size_t k = 0; k < samples.settle_steps; ++k) rollout.step(first.data(), first.data());
  Replay out;
  out.angles_rad.resize(samples.steps * n);
  const auto start = Clock::now();
  for (std::size_t k = 0; k < samples.steps; ++k) {
    if (!rollout.step(&samples.now[k * n], &samples.next[k * n])) break;
    for (std::size_t j = 0; j < n; ++j) {
      out.angles_rad[k * n + j] = rollout.joint_angle_rad(j) + offsets_rad[j];
    }
    ++out.steps;
  }
  out.seconds = seconds_since(start);
  out.end = to_string(rollout.end());
  return out;
}

Replay replay_in_mujoco(const ExportInput& input, const CommandSamples& samples,
                        const std::vector<double>& first, const std::vector<double>& offsets_rad,
                        const MujocoCheckOptions& options) {
  const RobotModel& model = input.model;
  const std::size_t n = model.actuators.size();
  MjcfOptions mjcf;
  mjcf.weld_root = options.hold_torso;
  // Placed by joint angle: the encoders read `first`.
  mjcf.placement_pose_rad = first;
  for (std::size_t j = 0; j < n; ++j) mjcf.placement_pose_rad[j] -= offsets_rad[j];
  mjcf.clearance_m = options.hold_torso ? kHeldTorsoClearance_m : -1.0;
  mjcf.armature = options.armature;
  std::string error;
  const detail::MjModelPtr m =
      detail::load_mjcf_text(export_mjcf(input, mjcf), mesh_assets(model), error);
  if (!m) throw ModelError("MuJoCo cannot load the exported model: " + error);
  const detail::MjDataPtr d(mj_makeData(m.get()));
  std::vector<int> qpos(n), actuator(n);
  for (std::size_t j = 0; j < n; ++j) {
    const char* name = model.actuators[j].name.c_str();
    const int joint = mj_name2id(m.get(), mjOBJ_JOINT, name);
    actuator[j] = mj_name2id(m.get(), mjOBJ_ACTUATOR, name);
    if (joint < 0 || actuator[j] < 0) throw ModelError(std::string("MJCF lacks joint ") + name);
    qpos[j] = m->jnt_qposadr[joint];
    d->qpos[qpos[j]] = first[j];
  }
  mj_forward(m.get(), d.get());
  std::vector<char> next_angle(n);  // per joint: the law's target is the angle at step end
  for (std::size_t j = 0; j < n; ++j) {
    next_angle[j] =
        servo_export_rule(actuator_servo_name(model, input.servo, j)).command_is_next_angle;
  }
  for (std::size_t k = 0; k < samples.settle_steps; ++k) {
    for (std::size_t j = 0; j < n; ++j) d->ctrl[actuator[j]] = first[j];
    mj_step(m.get(), d.get());
  }
  Replay out;
  out.angles_rad.resize(samples.steps * n);
  const auto start = Clock::now();
  for (std::size_t k = 0; k < samples.steps; ++k) {
    for (std::size_t j = 0; j < n; ++j) {
      d->ctrl[actuator[j]] = next_angle[j] ? samples.next[k * n + j] : samples.now[k * n + j];
    }
    mj_step(m.get(), d.get());
    for (std::size_t j = 0; j < n; ++j) out.angles_rad[k * n + j] = d->qpos[qpos[j]];
  }
  out.seconds = seconds_since(start);
  out.steps = samples.steps;
  out.geoms = static_cast<std::size_t>(m->ngeom);
  for (int g = 0; g < m->ngeom; ++g) out.visual_geoms += m->geom_group[g] == 1 ? 1 : 0;
  return out;
}

}  // namespace

MujocoComparison compare_with_mujoco(const ExportInput& input, const CommandTrajectory& commands,
                                     const MujocoCheckOptions& options) {
  const RobotModel& model = input.model;
  const std::size_t n = model.actuators.size();
  if (commands.joints() != n) {
    throw InputError("", 0, "commands",
                     "the trajectory has " + std::to_string(commands.joints()) + " joints, robot " +
                         model.name + " has " + std::to_string(n));
  }
  const CommandSamples samples = sample_commands(commands, input.dt_s, options.settle_s);
  std::vector<double> first(n);
  for (std::size_t j = 0; j < n; ++j) first[j] = commands.angle_rad(0, j);
  std::vector<double> offsets_rad;
  for (const ActuatorExport& a : export_actuators(input))
    offsets_rad.push_back(a.mounting_offset_rad);
  const Replay ode =
      replay_in_motoflex(input, samples, first, offsets_rad, options, StepSolver::kStep);
  const Replay quick =
      replay_in_motoflex(input, samples, first, offsets_rad, options, StepSolver::kQuickStep);
  const Replay sparse =
      replay_in_motoflex(input, samples, first, offsets_rad, options, StepSolver::kSparseStep);
  const Replay mujoco = replay_in_mujoco(input, samples, first, offsets_rad, options);

  MujocoComparison out;
  out.joints = model.actuator_names();
  out.steps = ode.steps;
  out.motoflex_end = ode.end;
  out.mujoco_version = mj_versionString();
  out.geoms = mujoco.geoms;
  out.visual_geoms = mujoco.visual_geoms;
  out.rms_deg_per_joint.assign(n, 0.0);
  constexpr double kDeg = 180.0 / M_PI;
  double total = 0.0;
  for (std::size_t k = 0; k < ode.steps; ++k) {
    for (std::size_t j = 0; j < n; ++j) {
      const double e = (mujoco.angles_rad[k * n + j] - ode.angles_rad[k * n + j]) * kDeg;
      out.rms_deg_per_joint[j] += e * e;
      out.max_abs_deg = std::max(out.max_abs_deg, std::abs(e));
      total += e * e;
    }
  }
  if (ode.steps > 0) {
    for (double& r : out.rms_deg_per_joint) r = std::sqrt(r / ode.steps);
    out.rms_deg = std::sqrt(total / (ode.steps * n));
  }
  out.motoflex_steps_per_s = ode.seconds > 0.0 ? ode.steps / ode.seconds : 0.0;
  out.motoflex_quick_steps_per_s = quick.seconds > 0.0 ? quick.steps / quick.seconds : 0.0;
  out.rms_deg_quick = rms_deg_between(mujoco, quick, n);
  out.motoflex_sparse_steps_per_s = sparse.seconds > 0.0 ? sparse.steps / sparse.seconds : 0.0;
  out.rms_deg_sparse = rms_deg_between(mujoco, sparse, n);
  out.rms_deg_sparse_vs_step = rms_deg_between(ode, sparse, n);
  out.mujoco_steps_per_s = mujoco.seconds > 0.0 ? mujoco.steps / mujoco.seconds : 0.0;
  return out;
}

}  // namespace motoflex
