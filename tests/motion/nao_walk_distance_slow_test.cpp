// How far the walks of the reference data get: each walk recorded from the MoToFlex truth model
// (scenarios/truth/nao_motoflex.yaml → reference_data/nao) is simulated twice, as its scenario
// says (rigid legs, ideal servos) and as it was recorded (the truth file's servo and physics,
// the recording's truth parameters from reference_data/nao/truth/, the recording's noise seed),
// and the torso's forward travel is printed as a table: distance, mean speed over the 8 s of
// stepping, and where a walk ended early. The two long-step walks that are not recorded are
// printed too.

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "motoflex/core/random_stream.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/rollout.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

struct Travel {
  RolloutEnd end = RolloutEnd::kCompleted;
  double end_time_s = 0.0;
  std::size_t frames = 0;
  double distance_m = 0.0;     // torso CoM, x, first to last frame
  double stepping_mm_s = 0.0;  // torso CoM x from 1 s to 9 s (frames at 100 Hz) / 8 s
  double sideways_m = 0.0;     // torso CoM, y, first to last frame
};

Travel travel_of(const Scenario& scenario) {
  const RolloutResult result =
      run_rollout(*scenario.model, scenario.parameters, scenario.commands, scenario.rollout);
  Travel travel;
  travel.end = result.end;
  travel.end_time_s = result.end_time_s;
  travel.frames = result.frames_completed;
  const std::size_t last = result.frames_completed - 1;
  const auto x_at = [&](std::size_t frame) {
    return result.torso_position_m[3 * std::min(frame, last)];
  };
  travel.distance_m = x_at(last) - x_at(0);
  travel.stepping_mm_s = 1e3 * (x_at(900) - x_at(100)) / 8.0;
  travel.sideways_m = result.torso_position_m[3 * last + 1] - result.torso_position_m[1];
  return travel;
}

TEST(NaoWalkDistance, ReferenceWalksOnIdealServosAndOnTheTruthModel) {
  const fs::path source = MOTOFLEX_SOURCE_DIR;
  const std::string truth_file = (source / "scenarios/truth/nao_motoflex.yaml").string();
  const YamlValue truth = YamlValue::load_file(truth_file);
  // The recording set-up of `motoflex record` (src/cli/cmd_record.cpp).
  ScenarioOverrides recorded;
  recorded.servo = truth.at("servo").as_string();
  const YamlValue physics = truth.at("physics");
  recorded.flex_sub_bodies = physics.at("flex_sub_bodies").as_int();
  recorded.gear_substeps = physics.at("gear_substeps").as_int();
  recorded.settle_s = physics.at("settle_s").as_double();
  const auto seed = static_cast<std::uint64_t>(truth.at("seed").as_int());

  struct Walk {
    std::string name;
    std::string description;
    Scenario ideal, recorded;
    Travel on_ideal, on_truth;
  };
  std::vector<Walk> walks;
  const std::vector<YamlValue> recordings = truth.at("recordings").items();
  for (std::size_t r = 0; r < recordings.size(); ++r) {
    const std::string name = recordings[r].at("name").as_string();
    if (name.find("walk") == std::string::npos) continue;
    const std::string scenario_path =
        recordings[r].resolve_path(recordings[r].at("scenario").as_string());
    ScenarioOverrides overrides = recorded;
    overrides.parameters_json = (source / "reference_data/nao/truth" / (name + ".json")).string();
    Walk walk{name, "", load_scenario(scenario_path), load_scenario(scenario_path, overrides),
              {},   {}};
    walk.recorded.rollout.seed = mix64(seed * 0x100000001B3ULL + r);
    walk.description = walk.ideal.motion_description;
    walks.push_back(std::move(walk));
  }
  ASSERT_EQ(walks.size(), 6u);  // four training and two validation walks
  // The two long-step walks are not recorded (they need knee speeds a real Nao lacks); the
  // truth model walks them with the recordings' parameters, for the table.
  const std::size_t recorded_walks = walks.size();
  for (const char* extra : {"nao_walk_150_2.yaml", "nao_walk_200_2.yaml"}) {
    const std::string scenario_path = (source / "scenarios/walks" / extra).string();
    ScenarioOverrides overrides = recorded;
    overrides.parameters_json =
        (source / "reference_data/nao/truth/train/walk_050mm_2s.json").string();
    Walk walk{extra, "", load_scenario(scenario_path), load_scenario(scenario_path, overrides),
              {},    {}};
    walk.recorded.rollout.seed = seed;
    walk.description = walk.ideal.motion_description;
    walks.push_back(std::move(walk));
  }

  // Two threads (rollouts share nothing mutable; dWorldStep results do not depend on threads).
  std::atomic<std::size_t> next{0};
  const auto work = [&] {
    for (std::size_t i = next++; i < walks.size(); i = next++) {
      walks[i].on_ideal = travel_of(walks[i].ideal);
      walks[i].on_truth = travel_of(walks[i].recorded);
    }
  };
  std::thread helper(work);
  work();
  helper.join();

  std::printf(
      "[ distance ] walk                     commanded                      ideal servos: "
      "m, mm/s   truth model: m, mm/s, sideways m\n");
  for (std::size_t i = 0; i < walks.size(); ++i) {
    const Walk& walk = walks[i];
    const Travel& ideal = walk.on_ideal;
    const Travel& truth_model = walk.on_truth;
    const std::string ending = truth_model.end == RolloutEnd::kCompleted
                                   ? std::string("completed")
                                   : std::string(to_string(truth_model.end)) + " at " +
                                         std::to_string(truth_model.end_time_s) + " s";
    std::printf("[ distance ] %-24s %-36s %6.3f %6.1f   %6.3f %6.1f %+6.3f  %s\n",
                walk.name.c_str(), walk.description.c_str(), ideal.distance_m, ideal.stepping_mm_s,
                truth_model.distance_m, truth_model.stepping_mm_s, truth_model.sideways_m,
                ending.c_str());
    // Ideal servos follow the plan to the last frame.
    EXPECT_EQ(ideal.end, RolloutEnd::kCompleted) << walk.name;
    EXPECT_EQ(ideal.frames, walk.ideal.commands.frames()) << walk.name;
    EXPECT_GT(ideal.distance_m, 0.3) << walk.name;
    if (i >= recorded_walks) continue;
    // The truth model stays up for the whole recording (reference_data/nao has every frame),
    // and its servos, lagging behind the commands, never gain ground on the ideal ones.
    EXPECT_EQ(truth_model.end, RolloutEnd::kCompleted) << walk.name;
    EXPECT_EQ(truth_model.frames, walk.recorded.commands.frames()) << walk.name;
    EXPECT_LT(truth_model.distance_m, ideal.distance_m) << walk.name;
  }
}

}  // namespace
}  // namespace motoflex
