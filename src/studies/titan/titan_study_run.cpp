#include "titan_study_run.hpp"

#include <time.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <stdexcept>

namespace motoflex::detail {
namespace {

double thread_cpu_s() {
  timespec now{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &now);
  return static_cast<double>(now.tv_sec) + 1e-9 * static_cast<double>(now.tv_nsec);
}

}  // namespace

void check_titan_study_setup(const TitanStudySetup& setup) {
  if (!setup.model) throw std::invalid_argument("TITAN study: no robot model");
  const std::string& servo = setup.rollout.servo;
  if (servo != "velocity" && servo != "ideal") {
    throw std::invalid_argument(
        "TITAN study: servo '" + servo +
        "' adds torques outside ODE's constraints, which joint feedback (eq. 4-5) cannot see; "
        "use velocity (the paper's) or ideal");
  }
  if (setup.servo_lead && servo != "velocity") {
    throw std::invalid_argument("TITAN study: servo_lead needs the velocity servo");
  }
  if (!(setup.command_rate_hz > 0.0)) {
    throw std::invalid_argument("TITAN study: command rate must be positive");
  }
}

CommandTrajectory titan_study_commands(const TitanStudySetup& setup,
                                       const TitanKinematics& kinematics,
                                       const TitanFootPlan& plan) {
  TitanCommandOptions options;
  options.rate_hz = setup.command_rate_hz;
  if (setup.servo_lead) {
    options.lead_gain_per_s = velocity_servo_gains_per_s(*setup.model, setup.parameters);
  }
  return titan_command_trajectory(kinematics, plan, options);
}

ProbeRunEnd run_titan_probe_rollout(const TitanStudySetup& setup, const TitanKinematics& kinematics,
                                    const CommandTrajectory& commands, double settle_s,
                                    double duration_s, bool with_probe,
                                    const ProbeStepObserver& observer) {
  const RobotModel& model = *setup.model;
  const std::size_t n = model.actuators.size();
  const double dt = setup.rollout.dt_s;
  std::vector<double> now(n), next(n);
  std::size_t hint_now = 0, hint_next = 0;
  const double start = commands.start_s();
  commands.sample(start, now.data(), hint_now);
  const std::vector<double> first = now;

  ProbeRunEnd result;
  Rollout rollout(model, setup.parameters, setup.rollout, first);
  // Declared after the rollout: destroyed first, so it can switch the feedback off.
  std::unique_ptr<TitanTorqueProbe> probe;
  if (with_probe) probe = std::make_unique<TitanTorqueProbe>(model, kinematics, rollout);

  const auto settle_steps = static_cast<std::size_t>(std::llround(settle_s / dt));
  for (std::size_t k = 0; k < settle_steps && rollout.end() == RolloutEnd::kCompleted; ++k) {
    rollout.step(first.data(), first.data());
  }
  const auto steps = static_cast<std::size_t>(std::llround(duration_s / dt));
  const auto wall_start = std::chrono::steady_clock::now();
  const double cpu_start = thread_cpu_s();
  for (std::size_t k = 0; k < steps && rollout.end() == RolloutEnd::kCompleted; ++k) {
    const double t = static_cast<double>(k) * dt;
    commands.sample(start + t, now.data(), hint_now);
    commands.sample(start + t + dt, next.data(), hint_next);
    if (probe) probe->before_step();
    if (!rollout.step(now.data(), next.data())) break;
    if (probe) probe->after_step();
    ++result.steps;
    if (observer) observer(static_cast<double>(k + 1) * dt, probe.get());
  }
  result.wall_s =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  result.cpu_s = thread_cpu_s() - cpu_start;
  result.end = rollout.end();
  result.detail = rollout.end_detail();
  return result;
}

}  // namespace motoflex::detail
