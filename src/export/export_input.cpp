#include "motoflex/export/export_input.hpp"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "motoflex/core/build_info.hpp"
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

std::vector<ProvenanceDataFile> data_files(const nlohmann::json& p, const std::string& path) {
  std::vector<ProvenanceDataFile> files;
  if (!p.contains("data")) return files;
  if (!p["data"].is_array()) throw InputError(path, 0, "provenance.data", "expected an array");
  for (const auto& file : p["data"]) {
    if (!file.is_object()) throw InputError(path, 0, "provenance.data", "expected objects");
    files.push_back({string_field(file, "role", path), string_field(file, "path", path),
                     string_field(file, "hash", path)});
  }
  return files;
}

// The 95 % intervals of summary.json beside best.json, when the fit computed them.
void add_intervals(const std::string& best_path, std::vector<ProvenanceFitted>& fitted) {
  const std::filesystem::path summary =
      std::filesystem::path(best_path).parent_path() / "summary.json";
  std::ifstream in(summary);
  if (!in) return;
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (json.is_discarded() || !json.contains("confidence_intervals")) return;
  const nlohmann::json& intervals = json["confidence_intervals"];
  for (auto& f : fitted) {
    if (!intervals.contains(f.name)) continue;
    const nlohmann::json& i = intervals[f.name];
    if (i.is_object() && i.contains("lower") && i["lower"].is_number()) f.lower = i["lower"];
    if (i.is_object() && i.contains("upper") && i["upper"].is_number()) f.upper = i["upper"];
    if (i.is_object() && i.contains("identified") && i["identified"].is_boolean()) {
      f.identified = i["identified"].get<bool>();
    }
    if (i.is_array() && i.size() == 2 && i[0].is_number() && i[1].is_number()) {
      f.lower = i[0];
      f.upper = i[1];
    }
  }
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.9g", value);
  return text;
}

}  // namespace

std::vector<std::string> provenance_lines(const FitProvenance& p, const std::string& servo) {
  std::vector<std::string> lines = {std::string("exported_by: motoflex ") + version(),
                                    "servo: " + servo};
  const auto add = [&lines](const char* key, const std::string& value) {
    if (!value.empty()) lines.push_back(std::string(key) + ": " + value);
  };
  add("source", p.source_path.empty() ? "robot defaults (no fit)" : p.source_path);
  add("fit", p.fit_config);
  add("run", p.run_dir);
  add("config_hash", p.config_hash);
  if (p.fitness) add("fitness", number_text(*p.fitness));
  add("date", p.date);
  add("fit_motoflex_version", p.motoflex_version);
  for (const auto& file : p.data) add("data", file.role + " " + file.path + " #" + file.hash);
  for (const auto& f : p.fitted) {
    std::string text = f.name + " = " + number_text(f.value);
    if (std::isfinite(f.lower) && std::isfinite(f.upper)) {
      text += " [" + number_text(f.lower) + ", " + number_text(f.upper) + "] (95 %)";
    }
    if (!f.identified) text += " unidentified by the data";
    add("fitted", text);
  }
  return lines;
}

std::string provenance_comment(const FitProvenance& provenance, const std::string& servo) {
  std::string text = " motoflex provenance:\n";
  for (const auto& line : provenance_lines(provenance, servo)) text += "      " + line + "\n";
  std::string safe;
  for (const char c : text) {
    safe += c;
    if (c == '-' && safe.size() >= 2 && safe[safe.size() - 2] == '-')
      safe.insert(safe.size() - 1, " ");
  }
  return safe + "  ";
}

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
        if (value.is_number()) provenance.fitted.push_back({name, value.get<double>()});
      }
      add_intervals(path, provenance.fitted);
    }
    if (document.contains("provenance")) {
      const nlohmann::json& p = document["provenance"];
      if (!p.is_object()) throw InputError(path, 0, "provenance", "expected an object");
      provenance.fit_config = string_field(p, "fit", path);
      provenance.config_hash = string_field(p, "config_hash", path);
      provenance.robot = string_field(p, "robot", path);
      provenance.date = string_field(p, "date", path);
      provenance.motoflex_version = string_field(p, "motoflex_version", path);
      provenance.run_dir = string_field(p, "run", path);
      provenance.data = data_files(p, path);
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
