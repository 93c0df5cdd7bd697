#pragma once

#include <string>

#include "motoflex/io/joint_log.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {

// A joint log of what a rollout commanded and measured (only the frames it completed), with
// IMU roll/pitch, described by `meta`.
JointLog joint_log_from_rollout(const RolloutResult& result, const JointLogMeta& meta);

}  // namespace motoflex
