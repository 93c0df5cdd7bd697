#include <cmath>

#include "motoflex/core/error.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

void record_frame(Rollout& rollout, RolloutResult& result, std::size_t frame,
                  const CommandTrajectory& commands, bool torques) {
  const std::size_t n = rollout.joints();
  result.time_s.push_back(commands.time_s(frame) - commands.start_s());
  for (std::size_t j = 0; j < n; ++j) {
    result.commanded_rad.push_back(commands.angle_rad(frame, j));
    result.measured_rad.push_back(rollout.encoder_rad(j));
    if (torques) result.joint_torque_nm.push_back(rollout.actuator_torque_nm(j));
  }
  double roll = 0.0, pitch = 0.0;
  rollout.imu_roll_pitch(roll, pitch);
  result.imu_roll_rad.push_back(roll);
  result.imu_pitch_rad.push_back(pitch);
  const Eigen::Vector3d p = rollout.torso_position_m();
  result.torso_position_m.insert(result.torso_position_m.end(), {p.x(), p.y(), p.z()});
  for (std::size_t f = 0; f < rollout.foot_count(); ++f) {
    result.foot_force_z_n.push_back(rollout.foot_force_n(f).z());
  }
  result.frames_completed = frame + 1;
}

}  // namespace

RolloutResult run_rollout(const RobotModel& model, const ParameterSet& parameters,
                          const CommandTrajectory& commands, const RolloutOptions& options,
                          const FrameObserver& observer) {
  RolloutResult result;
  result.joint_names = model.actuator_names();
  result.frames_requested = commands.frames();
  const std::size_t n = model.actuators.size();
  if (commands.joints() != n) {
    result.end = RolloutEnd::kModelError;
    result.end_detail = "commanded trajectory has the wrong number of joints";
    return result;
  }
  std::vector<double> first(n);
  for (std::size_t j = 0; j < n; ++j) first[j] = commands.angle_rad(0, j);

  std::unique_ptr<Rollout> rollout;
  try {
    rollout = std::make_unique<Rollout>(model, parameters, options, first);
  } catch (const ModelError& error) {
    result.end = RolloutEnd::kModelError;
    result.end_detail = error.what();
    return result;
  }

  // Every frame's record is sized here, so the stepping loop below never reallocates.
  const std::size_t frames = commands.frames();
  result.time_s.reserve(frames);
  result.commanded_rad.reserve(frames * n);
  result.measured_rad.reserve(frames * n);
  if (options.record_torques) result.joint_torque_nm.reserve(frames * n);
  result.imu_roll_rad.reserve(frames);
  result.imu_pitch_rad.reserve(frames);
  result.torso_position_m.reserve(3 * frames);
  result.foot_force_z_n.reserve(rollout->foot_count() * frames);

  // Settle on the first commanded pose so the servos reach a steady state before t = 0.
  const auto settle_steps = static_cast<std::size_t>(std::llround(options.settle_s / options.dt_s));
  std::size_t hint_supply = 0;
  if (commands.has_supply()) {
    rollout->set_logged_supply_v(commands.supply_v_at(commands.start_s(), hint_supply));
  }
  for (std::size_t k = 0; k < settle_steps; ++k) {
    if (!rollout->step(first.data(), first.data())) break;
    ++result.physics_steps;
  }

  std::vector<double> now(n), next(n);
  std::size_t hint_now = 0, hint_next = 0;
  const double start = commands.start_s();
  const double half_step = 0.5 * options.dt_s;
  std::size_t frame = 0;
  std::size_t step = 0;
  while (rollout->end() == RolloutEnd::kCompleted) {
    const double t = step * options.dt_s;  // time since the trajectory start, before this step
    bool stop = false;
    while (frame < commands.frames() && commands.time_s(frame) - start <= t + half_step) {
      record_frame(*rollout, result, frame, commands, options.record_torques);
      if (observer && !observer(result, frame)) stop = true;
      ++frame;
      if (stop) break;
    }
    if (stop) {
      result.end = RolloutEnd::kStoppedEarly;
      result.end_time_s = step * options.dt_s;
      return result;
    }
    if (frame >= commands.frames()) break;
    commands.sample(start + t, now.data(), hint_now);
    commands.sample(start + t + options.dt_s, next.data(), hint_next);
    if (commands.has_supply()) {
      rollout->set_logged_supply_v(commands.supply_v_at(start + t, hint_supply));
    }
    rollout->step(now.data(), next.data());
    ++result.physics_steps;
    ++step;
  }
  result.end = rollout->end();
  result.end_detail = rollout->end_detail();
  result.end_time_s = step * options.dt_s;
  return result;
}

}  // namespace motoflex
