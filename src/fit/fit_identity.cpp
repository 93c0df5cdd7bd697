// The identity of a fit: every input that decides its generations, with file contents by hash.
// A run folder's checkpoint carries its hash, so `resume` refuses a config that changed.

#include <filesystem>
#include <fstream>
#include <sstream>

#include "motoflex/core/text_hash.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/io/joint_log.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

std::string file_hash(const std::string& path) {
  if (!fs::exists(path)) return "absent";
  std::ifstream in(path, std::ios::binary);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return hash_text(buffer.str());
}

}  // namespace

nlohmann::json fit_identity(const FitConfig& config) {
  nlohmann::ordered_json id;
  id["format"] = 1;
  id["scenario"] = file_hash(config.scenario_path);
  id["robot_yaml"] =
      file_hash((fs::path(config.scenario->model->directory) / "robot.yaml").string());
  id["urdf"] = file_hash(config.scenario->model->urdf_path);
  for (const auto& log : config.train_logs) {
    id["train"].push_back({fs::path(log).filename().string(), file_hash(log),
                           file_hash(joint_log_sidecar_path(log))});
  }
  for (const auto& log : config.validation_logs) {
    id["validation"].push_back({fs::path(log).filename().string(), file_hash(log)});
  }
  for (const auto& p : config.free_parameters) {
    id["free"].push_back({{"name", p.name},
                          {"targets", p.targets},
                          {"lower", p.lower},
                          {"upper", p.upper},
                          {"log", p.log_scale},
                          {"start", p.start}});
  }
  for (const auto& [name, value] : config.fixed) id["fixed"][name] = value;
  for (const auto& [name, value] : config.incumbent) id["incumbent"][name] = value;
  if (!config.effects.empty()) id["effects"] = config.effects;
  id["flex_sub_bodies"] = config.scenario->model->structure.flex_sub_bodies;
  id["fitness"] = {{"m", config.fitness.m},
                   {"settle_s", config.fitness.settle_s},
                   {"weights", config.fitness.joint_weights}};
  // Only when used, so that the hashes of existing joint-only run dirs stay valid.
  if (config.fitness.imu_weight > 0.0) id["fitness"]["imu_weight"] = config.fitness.imu_weight;
  if (config.fitness.window_s > 0.0) id["fitness"]["window_s"] = config.fitness.window_s;
  if (config.fitness.absolute_error) id["fitness"]["error"] = "absolute";
  id["strategy"] = strategy_to_json(config.strategy);
  // Only when asked for, so that the hashes of existing run dirs stay valid.
  if (!config.polish.method.empty()) id["polish"] = polish_to_json(config.polish);
  id["seed"] = config.seed;
  return nlohmann::json(id);
}

}  // namespace motoflex
