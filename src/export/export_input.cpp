#include "motoflex/export/export_input.hpp"

#include <ctime>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "motoflex/core/error.hpp"

namespace motoflex {
namespace {

std::string string_field(const nlohmann::json& object, const char* key, const std::string& path) {
  if (!object.contains(key) || object[key].is_null()) return "";
  if (!object[key].is_string()) {
    throw InputError(path, 0, std::string("provenance.") + key, "expected a string");
  }
  return object[key].get<std::string>();
}

}  // namespace

FitProvenance read_fitted_parameters(const std::string& path, const std::string& robot_name,
                                     ParameterSet& parameters) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot open the parameter file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  const std::string text = buffer.str();
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    throw InputError(path, 0, "", std::string("invalid JSON: ") + error.what());
  }
  FitProvenance provenance;
  provenance.source_path = path;
  if (document.is_object() && document.contains("parameters")) {
    if (document.contains("fitness")) {
      if (!document["fitness"].is_number())
        throw InputError(path, 0, "fitness", "expected a number");
      provenance.fitness = document["fitness"].get<double>();
    }
    if (document.contains("free")) {
      if (!document["free"].is_object()) throw InputError(path, 0, "free", "expected an object");
      for (const auto& [name, value] : document["free"].items()) {
        provenance.free_parameters.push_back(name);
      }
    }
    if (document.contains("provenance")) {
      const nlohmann::json& p = document["provenance"];
      if (!p.is_object()) throw InputError(path, 0, "provenance", "expected an object");
      provenance.fit_config = string_field(p, "fit", path);
      provenance.config_hash = string_field(p, "config_hash", path);
      provenance.robot = string_field(p, "robot", path);
      provenance.date = string_field(p, "date", path);
      provenance.motoflex_version = string_field(p, "motoflex_version", path);
    }
    if (!provenance.robot.empty() && provenance.robot != robot_name) {
      throw InputError(path, 0, "provenance.robot",
                       "the parameters were fitted for robot '" + provenance.robot + "', not '" +
                           robot_name + "'");
    }
  }
  apply_parameter_json_text(text, path, parameters);
  return provenance;
}

}  // namespace motoflex
