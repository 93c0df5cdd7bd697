// Seed 000 §II-A: how long a 10 s crawl takes to simulate (the paper: 60 s on a 2011 PC).

#include <cmath>
#include <stdexcept>

#include "motoflex/studies/titan/titan_study.hpp"
#include "titan_study_run.hpp"

namespace motoflex {

TitanCrawlTiming time_titan_crawl(const TitanStudySetup& setup, TitanPosture posture,
                                  double simulated_s, int repeats) {
  detail::check_titan_study_setup(setup);
  if (!(simulated_s > 0.0)) throw std::invalid_argument("TITAN crawl timing: bad duration");
  if (repeats < 1) throw std::invalid_argument("TITAN crawl timing: repeats must be >= 1");
  TitanCrawlOptions gait_options;
  gait_options.posture = posture;
  gait_options.periods = static_cast<int>(std::ceil(simulated_s / gait_options.period_s));
  const TitanCrawl gait(gait_options);
  const TitanKinematics kinematics(*setup.model);
  const CommandTrajectory commands = detail::titan_study_commands(setup, kinematics, gait);
  constexpr double kSettle_s = 0.5;
  TitanCrawlTiming timing;
  timing.simulated_s = simulated_s;
  for (int run = 0; run < repeats; ++run) {
    const detail::ProbeRunEnd with_probe = detail::run_titan_probe_rollout(
        setup, kinematics, commands, kSettle_s, simulated_s, true, {});
    if (timing.wall_runs_s.empty() || with_probe.wall_s < timing.wall_s) {
      timing.wall_s = with_probe.wall_s;
      timing.cpu_s = with_probe.cpu_s;
    }
    timing.wall_runs_s.push_back(with_probe.wall_s);
    timing.steps = with_probe.steps;
  }
  timing.wall_bare_s = detail::run_titan_probe_rollout(setup, kinematics, commands, kSettle_s,
                                                       simulated_s, false, {})
                           .wall_s;
  return timing;
}

}  // namespace motoflex
