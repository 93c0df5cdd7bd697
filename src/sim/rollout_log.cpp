#include "motoflex/sim/rollout_log.hpp"

namespace motoflex {

JointLog joint_log_from_rollout(const RolloutResult& result, const JointLogMeta& meta) {
  JointLog log;
  log.meta = meta;
  log.joint_names = result.joint_names;
  const std::size_t frames = result.frames_completed;
  const std::size_t n = result.joints();
  log.time_s.assign(result.time_s.begin(), result.time_s.begin() + frames);
  log.commanded_rad.assign(result.commanded_rad.begin(), result.commanded_rad.begin() + frames * n);
  log.measured_rad.assign(result.measured_rad.begin(), result.measured_rad.begin() + frames * n);
  log.imu_roll_rad.assign(result.imu_roll_rad.begin(), result.imu_roll_rad.begin() + frames);
  log.imu_pitch_rad.assign(result.imu_pitch_rad.begin(), result.imu_pitch_rad.begin() + frames);
  return log;
}

}  // namespace motoflex
