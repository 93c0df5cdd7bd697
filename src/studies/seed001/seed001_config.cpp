#include "motoflex/studies/seed001/seed001_config.hpp"

#include <algorithm>
#include <filesystem>
#include <set>

#include "motoflex/core/build_info.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/motion/nao_walk.hpp"

namespace motoflex {
namespace {

void require_unique(std::set<std::string>& names, const YamlValue& field) {
  const std::string name = field.as_string();
  if (name.empty()) field.fail("must not be empty");
  if (!names.insert(name).second) field.fail("'" + name + "' is listed twice");
}

Seed001Walk read_walk(const YamlValue& item) {
  item.require_keys_within(
      {"name", "scenario", "commands", "step_s", "steady_s", "figure", "variants"});
  Seed001Walk walk;
  walk.name = item.at("name").as_string();
  if (const auto variants = item.find("variants")) {
    walk.variants = variants->as_string_list();
    if (walk.variants.empty()) variants->fail("no variants listed (leave the key out for all)");
  }
  walk.figure = item.get_string("figure", "");
  if (walk.figure != "" && walk.figure != "pitch" && walk.figure != "roll") {
    item.at("figure").fail("expected 'pitch' (Fig. 3) or 'roll' (Fig. 4)");
  }
  if (item.has("scenario") == item.has("commands")) {
    item.at("name").fail("give either `scenario` (a planned walk) or `commands` (a command file)");
  }
  if (const auto scenario = item.find("scenario")) {
    walk.scenario_path = scenario->resolve_path(scenario->as_string());
    if (item.has("step_s") || item.has("steady_s")) {
      item.at("scenario").fail("a planned walk takes step_s and steady_s from its plan");
    }
    return walk;
  }
  const YamlValue commands = item.at("commands");
  walk.commands_path = commands.resolve_path(commands.as_string());
  walk.step_s = item.at("step_s").as_double();
  if (!(walk.step_s > 0.0 && walk.step_s <= 10.0)) item.at("step_s").fail("must be in (0, 10] s");
  if (const auto steady = item.find("steady_s")) {
    const std::vector<double> window = steady->as_double_list();
    if (window.size() != 2 || !(window[0] >= 0.0 && window[1] > window[0] && window[1] <= 3600.0)) {
      steady->fail("expected [from_s, to_s] with 0 <= from_s < to_s <= 3600");
    }
    walk.steady_start_s = window[0];
    walk.steady_end_s = window[1];
  }
  return walk;
}

}  // namespace

void set_walk_command_file(Seed001Config& config, const std::string& name,
                           const std::string& path) {
  for (Seed001Walk& walk : config.walks) {
    if (walk.name != name) continue;
    if (!walk.replays_commands()) {
      throw InputError(config.path, 0, "--commands",
                       "walk '" + name + "' is a planned walk, not a command file");
    }
    walk.commands_path = path;
    return;
  }
  throw InputError(config.path, 0, "--commands", "no walk '" + name + "' in the experiment");
}

Seed001Config load_seed001_config(const std::string& path) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within({"walks", "variants", "zmp"});
  Seed001Config config;
  config.path = path;
  std::set<std::string> walk_names;
  for (const YamlValue& item : root.at("walks").items()) {
    require_unique(walk_names, item.at("name"));
    config.walks.push_back(read_walk(item));
  }
  if (config.walks.empty()) root.at("walks").fail("no walks listed");
  std::set<std::string> variant_names;
  for (const YamlValue& item : root.at("variants").items()) {
    item.require_keys_within({"name", "scenario", "params", "physics", "pending"});
    require_unique(variant_names, item.at("name"));
    Seed001Variant variant;
    variant.name = item.at("name").as_string();
    variant.pending = item.get_string("pending", "");
    if (variant.pending.empty()) {
      variant.scenario_path = item.resolve_path(item.at("scenario").as_string());
      if (const auto params = item.find("params")) {
        variant.params_path = params->resolve_path(params->as_string());
      }
      variant.physics = item.find("physics");
    } else if (item.has("scenario") || item.has("params") || item.has("physics")) {
      item.at("pending").fail("a pending variant names no scenario, params or physics");
    }
    config.variants.push_back(std::move(variant));
  }
  if (config.variants.empty()) root.at("variants").fail("no variants listed");
  // Each walk's own variant list (read with the walk) names variants of the file.
  const std::vector<YamlValue> walk_items = root.at("walks").items();
  for (std::size_t w = 0; w < config.walks.size(); ++w) {
    for (const std::string& name : config.walks[w].variants) {
      if (!variant_names.count(name)) {
        walk_items[w].at("variants").fail("'" + name + "' is not a variant");
      }
    }
  }
  if (const auto zmp = root.find("zmp")) {
    zmp->require_keys_within({"walk", "search", "variants"});
    config.zmp.walk = zmp->at("walk").as_string();
    if (!walk_names.count(config.zmp.walk)) zmp->at("walk").fail("not one of the walks");
    const Seed001Walk& zmp_walk =
        *std::find_if(config.walks.begin(), config.walks.end(),
                      [&config](const Seed001Walk& walk) { return walk.name == config.zmp.walk; });
    if (zmp_walk.replays_commands()) {
      zmp->at("walk").fail("the ZMP experiment needs a planned walk, not a command file");
    }
    for (const auto& [option, values] : zmp->at("search").entries()) {
      if (!NaoWalkParams{}.numeric(option)) {
        values.fail("not a numeric walk option (NaoWalkParams)");
      }
      const std::vector<double> list = values.as_double_list();
      if (list.empty()) values.fail("no values to try");
      for (const double value : list) config.zmp.settings.push_back({option, value});
    }
    if (config.zmp.settings.empty()) zmp->at("search").fail("no walk option to search");
    config.zmp.variants = zmp->at("variants").as_string_list();
    for (const std::string& name : config.zmp.variants) {
      if (!variant_names.count(name)) zmp->at("variants").fail("'" + name + "' is not a variant");
      if (!zmp_walk.runs_under(name)) {
        zmp->at("variants")
            .fail("'" + name + "' is not among walk '" + zmp_walk.name + "''s variants");
      }
    }
  }
  return config;
}

std::string find_experiment_config(const std::string& name) {
  std::error_code error;
  if (std::filesystem::is_regular_file(name, error)) return name;
  const std::filesystem::path bundled =
      std::filesystem::path(data_directory()) / "scenarios" / "experiments" / (name + ".yaml");
  if (std::filesystem::is_regular_file(bundled, error)) return bundled.string();
  throw InputError(name, 0, "experiment",
                   "no such file, and no bundled experiment " + bundled.string());
}

}  // namespace motoflex
