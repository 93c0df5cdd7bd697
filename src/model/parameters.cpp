#include "motoflex/model/parameters.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "motoflex/core/error.hpp"
#include "motoflex/io/yaml_reader.hpp"

namespace motoflex {
namespace {

bool glob_match(const char* pattern, const char* text) {
  if (*pattern == '\0') return *text == '\0';
  if (pattern[0] == '*' && pattern[1] == '*') {
    for (const char* t = text;; ++t) {
      if (glob_match(pattern + 2, t)) return true;
      if (*t == '\0') return false;
    }
  }
  if (*pattern == '*') {
    for (const char* t = text;; ++t) {
      if (glob_match(pattern + 1, t)) return true;
      if (*t == '\0' || *t == '.') return false;
    }
  }
  return *text != '\0' && *pattern == *text && glob_match(pattern + 1, text + 1);
}

}  // namespace

bool parameter_pattern_matches(const std::string& pattern, const std::string& name) {
  return glob_match(pattern.c_str(), name.c_str());
}

namespace {

// Longest suffix first, so "_nm_s_per_rad" wins over "_per_rad" and "_rad".
constexpr std::array<std::pair<const char*, const char*>, 23> kUnitSuffixes = {{
    {"_nm_s_per_rad", "N·m·s/rad"},
    {"_v_s_per_rad", "V·s/rad"},
    {"_v_per_rad_s", "V/(rad·s)"},
    {"_nm_per_rad", "N·m/rad"},
    {"_nm_per_a", "N·m/A"},
    {"_v_per_rad", "V/rad"},
    {"_kg_m2", "kg·m²"},
    {"_per_nm", "1/(N·m)"},
    {"_rad_s", "rad/s"},
    {"_ticks", "tick"},
    {"_per_s", "1/s"},
    {"_ohm", "Ω"},
    {"_rad", "rad"},
    {"_bits", "bit"},
    {"_nm", "N·m"},
    {"_kg", "kg"},
    {"_hz", "Hz"},
    {"_v", "V"},
    {"_h", "H"},
    {"_s", "s"},
    {"_m", "m"},
    {"_n", "N"},
    {"_a", "A"},
}};

}  // namespace

std::string unit_from_parameter_name(const std::string& name) {
  const std::size_t dot = name.rfind('.');
  const std::string leaf = dot == std::string::npos ? name : name.substr(dot + 1);
  for (const auto& [suffix, unit] : kUnitSuffixes) {
    const std::string s(suffix);
    if (leaf.size() > s.size() && leaf.compare(leaf.size() - s.size(), s.size(), s) == 0) {
      return unit;
    }
  }
  return "1";
}

void ParameterRegistry::add(ParameterSpec spec) {
  if (index_.count(spec.name) != 0) {
    throw std::invalid_argument("duplicate parameter '" + spec.name + "'");
  }
  if (!(spec.lower < spec.upper)) {
    throw std::invalid_argument("parameter '" + spec.name + "': lower bound must be below upper");
  }
  domains_.push_back(parameter_domain(spec.name));
  index_.emplace(spec.name, specs_.size());
  specs_.push_back(std::move(spec));
}

std::optional<std::size_t> ParameterRegistry::find(const std::string& name) const {
  const auto it = index_.find(name);
  if (it == index_.end()) return std::nullopt;
  return it->second;
}

std::string ParameterRegistry::closest_name(const std::string& name) const {
  std::string best;
  int best_distance = 4;
  for (const auto& spec : specs_) {
    const int d = edit_distance(name, spec.name);
    if (d < best_distance) {
      best_distance = d;
      best = spec.name;
    }
  }
  return best;
}

ParameterSet::ParameterSet(const ParameterRegistry& registry) : registry_(&registry) {
  values_.reserve(registry.size());
  for (const auto& spec : registry.specs()) values_.push_back(spec.default_value);
}

double ParameterSet::get(const std::string& name) const {
  const auto index = registry_->find(name);
  if (!index) throw std::out_of_range("unknown parameter '" + name + "'");
  return values_[*index];
}

void ParameterSet::set(const std::string& name, double value) {
  const auto index = registry_->find(name);
  if (!index) throw std::out_of_range("unknown parameter '" + name + "'");
  set(*index, value);
}

void ParameterSet::set(std::size_t index, double value) {
  if (!std::isfinite(value)) {
    throw std::invalid_argument("parameter '" + registry_->spec(index).name +
                                "' must be a finite number");
  }
  values_.at(index) = value;
}

namespace {

std::string format_number(double value) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.10g", value);
  return buffer;
}

int line_at_byte(const std::string& text, std::size_t byte) {
  const std::size_t end = std::min(byte, text.size());
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(end), '\n'));
}

// Parses `text`, rejecting a key that appears twice in one object (nlohmann keeps the last
// silently, which would hide a mistake in a hand-edited file).
nlohmann::json parse_without_duplicates(const std::string& text, const std::string& source) {
  std::vector<std::set<std::string>> open_objects;
  std::string duplicate;
  const auto callback = [&](int, nlohmann::json::parse_event_t event, nlohmann::json& value) {
    using Event = nlohmann::json::parse_event_t;
    if (event == Event::object_start) open_objects.emplace_back();
    if (event == Event::object_end && !open_objects.empty()) open_objects.pop_back();
    if (event == Event::key && !open_objects.empty() && duplicate.empty() &&
        !open_objects.back().insert(value.get<std::string>()).second) {
      duplicate = value.get<std::string>();
    }
    return true;
  };
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text, callback);
  } catch (const nlohmann::json::parse_error& error) {
    throw InputError(source, line_at_byte(text, error.byte), "",
                     std::string("invalid JSON: ") + error.what());
  } catch (const nlohmann::json::exception& error) {  // e.g. 406: a number beyond double
    throw InputError(source, 0, "", std::string("invalid JSON: ") + error.what());
  }
  if (!duplicate.empty()) throw InputError(source, 0, duplicate, "given twice");
  return document;
}

void check_value(const ParameterSet& set, std::size_t index, double number,
                 const std::string& source, bool check_bounds,
                 const ParameterFileOptions& options) {
  const ParameterSpec& spec = set.registry().spec(index);
  const ParameterDomain& domain = set.registry().domain(index);
  if (!domain.contains(number)) {
    throw InputError(source, 0, spec.name,
                     format_number(number) + " is outside its domain (" + domain.describe() + ")");
  }
  if (!check_bounds || (number >= spec.lower && number <= spec.upper)) return;
  const std::string message = format_number(number) + " is outside its bounds [" +
                              format_number(spec.lower) + ", " + format_number(spec.upper) + "]";
  if (!options.allow_out_of_bounds) {
    throw InputError(source, 0, spec.name, message + " (--allow-out-of-bounds to use it anyway)");
  }
  std::fprintf(stderr, "motoflex: warning: %s: %s: %s\n", source.c_str(), spec.name.c_str(),
               message.c_str());
}

}  // namespace

void apply_parameter_json_text(const std::string& text, const std::string& source,
                               ParameterSet& set, const ParameterFileOptions& options) {
  nlohmann::json document = parse_without_duplicates(text, source);
  // A fit's output holds values inside the fit's bounds, which may be wider than the robot's.
  bool check_bounds = true;
  if (document.is_object() && document.contains("parameters") &&
      document["parameters"].is_object()) {
    document = document["parameters"];
    check_bounds = false;
  }
  if (!document.is_object()) {
    throw InputError(source, 0, "", "expected a JSON object of parameter name -> value");
  }
  for (const auto& [name, value] : document.items()) {
    const auto index = set.registry().find(name);
    if (!index) {
      const std::string hint = set.registry().closest_name(name);
      throw InputError(
          source, 0, name,
          "unknown parameter" + (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
    }
    if (!value.is_number()) throw InputError(source, 0, name, "expected a number");
    const double number = value.get<double>();
    if (!std::isfinite(number)) throw InputError(source, 0, name, "must be finite");
    check_value(set, *index, number, source, check_bounds, options);
    set.set(*index, number);
  }
}

void apply_parameter_json_file(const std::string& path, ParameterSet& set,
                               const ParameterFileOptions& options) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    throw InputError(path, 0, "", "is a folder, expected a parameter JSON file");
  }
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, "", "cannot open parameter file");
  std::stringstream buffer;
  buffer << in.rdbuf();
  apply_parameter_json_text(buffer.str(), path, set, options);
}

std::string parameter_set_to_json(const ParameterSet& set) {
  // nlohmann::ordered_json keeps registry order; doubles are printed to round-trip exactly.
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < set.registry().size(); ++i) {
    out[set.registry().spec(i).name] = set.get(i);
  }
  return out.dump(2) + "\n";
}

}  // namespace motoflex
