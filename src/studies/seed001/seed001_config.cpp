#include "motoflex/studies/seed001/seed001_config.hpp"

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

}  // namespace

Seed001Config load_seed001_config(const std::string& path) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within({"walks", "variants", "zmp"});
  Seed001Config config;
  config.path = path;
  std::set<std::string> walk_names;
  for (const YamlValue& item : root.at("walks").items()) {
    item.require_keys_within({"name", "scenario", "figure"});
    require_unique(walk_names, item.at("name"));
    Seed001Walk walk{item.at("name").as_string(),
                     item.resolve_path(item.at("scenario").as_string()),
                     item.get_string("figure", "")};
    if (walk.figure != "" && walk.figure != "pitch" && walk.figure != "roll") {
      item.at("figure").fail("expected 'pitch' (Fig. 3) or 'roll' (Fig. 4)");
    }
    config.walks.push_back(std::move(walk));
  }
  if (config.walks.empty()) root.at("walks").fail("no walks listed");
  std::set<std::string> variant_names;
  for (const YamlValue& item : root.at("variants").items()) {
    item.require_keys_within({"name", "scenario", "params", "pending"});
    require_unique(variant_names, item.at("name"));
    Seed001Variant variant;
    variant.name = item.at("name").as_string();
    variant.pending = item.get_string("pending", "");
    if (variant.pending.empty()) {
      variant.scenario_path = item.resolve_path(item.at("scenario").as_string());
      if (const auto params = item.find("params")) {
        variant.params_path = params->resolve_path(params->as_string());
      }
    } else if (item.has("scenario") || item.has("params")) {
      item.at("pending").fail("a pending variant names no scenario or params");
    }
    config.variants.push_back(std::move(variant));
  }
  if (config.variants.empty()) root.at("variants").fail("no variants listed");
  if (const auto zmp = root.find("zmp")) {
    zmp->require_keys_within({"walk", "search", "variants"});
    config.zmp.walk = zmp->at("walk").as_string();
    if (!walk_names.count(config.zmp.walk)) zmp->at("walk").fail("not one of the walks");
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
