#pragma once

// Internal to the TITAN-VIII studies: building the commands of a foot plan and stepping one
// rollout through them with a torque probe.

#include <functional>
#include <string>

#include "motoflex/studies/titan/titan_study.hpp"
#include "motoflex/studies/titan/titan_torque_probe.hpp"

namespace motoflex::detail {

// Throws std::invalid_argument unless the setup has a model, a motor-row servo (velocity or
// ideal: the feedback of eq. 4–5 sees only constraint forces, not torques added to the bodies)
// and servo_lead only with the velocity servo.
void check_titan_study_setup(const TitanStudySetup& setup);

// The plan's commanded angles, with the velocity servo's lead when setup.servo_lead.
CommandTrajectory titan_study_commands(const TitanStudySetup& setup,
                                       const TitanKinematics& kinematics,
                                       const TitanFootPlan& plan);

struct ProbeRunEnd {
  RolloutEnd end = RolloutEnd::kCompleted;
  std::string detail;
  double wall_s = 0.0;  // stepping of the motion phase only
  double cpu_s = 0.0;   // CPU time of the calling thread over the same stepping
  std::size_t steps = 0;
};

// Called after every step of the motion phase with the motion time at the end of the step;
// the probe is null when the run has none.
using ProbeStepObserver = std::function<void(double t_s, const TitanTorqueProbe* probe)>;

// Releases the robot in the first commanded pose (initial clearance of the model), holds that
// pose for settle_s, then follows the commands from their start for duration_s (clamped to the
// last frame after its end). Stops early when the rollout falls or diverges.
ProbeRunEnd run_titan_probe_rollout(const TitanStudySetup& setup, const TitanKinematics& kinematics,
                                    const CommandTrajectory& commands, double settle_s,
                                    double duration_s, bool with_probe,
                                    const ProbeStepObserver& observer);

}  // namespace motoflex::detail
