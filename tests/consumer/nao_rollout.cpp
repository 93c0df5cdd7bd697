// Loads a scenario through the installed motoflex package, runs one rollout of its motion and
// prints what happened. Exit 0 when every frame was simulated.
#include <cstdio>
#include <exception>

#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/rollout.hpp"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: nao_rollout SCENARIO.yaml\n");
    return 2;
  }
  try {
    motoflex::ScenarioOverrides overrides;
    overrides.duration_s = 2.0;
    const motoflex::Scenario scenario = motoflex::load_scenario(argv[1], overrides);
    const motoflex::RolloutResult result = motoflex::run_rollout(
        *scenario.model, scenario.parameters, scenario.commands, scenario.rollout);
    std::printf("%s: %zu of %zu frames, %s, torso at z = %.3f m\n", scenario.name.c_str(),
                result.frames_completed, result.frames_requested, motoflex::to_string(result.end),
                result.torso_position_m.empty() ? 0.0 : result.torso_position_m.back());
    return result.end == motoflex::RolloutEnd::kCompleted ? 0 : 1;
  } catch (const std::exception& error) {
    std::fprintf(stderr, "nao_rollout: %s\n", error.what());
    return 2;
  }
}
