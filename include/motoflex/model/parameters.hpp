#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "motoflex/model/parameter_domain.hpp"

namespace motoflex {

// One model parameter: a dotted name that ends in its unit (`gear.B.backlash_rad`), the unit,
// the default and the search bounds.
struct ParameterSpec {
  std::string name;
  std::string unit;  // e.g. "rad", "N·m/rad"; "1" for dimensionless
  double default_value = 0.0;
  double lower = 0.0;
  double upper = 0.0;
};

// The unit a parameter name declares by its suffix ("_nm_per_rad" → "N·m/rad"); "1" when the
// name has no unit suffix.
std::string unit_from_parameter_name(const std::string& name);

// Whether a parameter name matches a pattern: '*' matches any run of characters other than '.'
// ("joint.*.friction_nm"), "**" any run at all; everything else literally.
bool parameter_pattern_matches(const std::string& pattern, const std::string& name);

// The set of parameters a robot model has. Immutable once the model is loaded.
class ParameterRegistry {
 public:
  // Throws std::invalid_argument on a duplicate name or lower >= upper. Sets the spec's domain
  // from the parameter catalog.
  void add(ParameterSpec spec);

  std::optional<std::size_t> find(const std::string& name) const;
  bool contains(const std::string& name) const { return find(name).has_value(); }
  std::size_t size() const { return specs_.size(); }
  const ParameterSpec& spec(std::size_t index) const { return specs_.at(index); }
  // The physical domain of parameter `index` (from the parameter catalog).
  const ParameterDomain& domain(std::size_t index) const { return domains_.at(index); }
  const std::vector<ParameterSpec>& specs() const { return specs_; }
  // The registered name closest to `name` (for "did you mean" messages); empty if none close.
  std::string closest_name(const std::string& name) const;

 private:
  std::vector<ParameterSpec> specs_;
  std::vector<ParameterDomain> domains_;
  std::unordered_map<std::string, std::size_t> index_;
};

// Values for every parameter of a registry (defaults unless set). Cheap to copy; one per
// rollout or per individual.
class ParameterSet {
 public:
  explicit ParameterSet(const ParameterRegistry& registry);

  const ParameterRegistry& registry() const { return *registry_; }
  // Throws std::out_of_range naming the parameter when it does not exist.
  double get(const std::string& name) const;
  double get(std::size_t index) const { return values_.at(index); }
  // Throws std::out_of_range for unknown names and std::invalid_argument for non-finite values.
  void set(const std::string& name, double value);
  void set(std::size_t index, double value);
  const std::vector<double>& values() const { return values_; }

 private:
  const ParameterRegistry* registry_;
  std::vector<double> values_;
};

// How strictly a parameter file is read.
struct ParameterFileOptions {
  // A value outside the parameter's search bounds is an error unless this is set (then a
  // warning on stderr). Only checked for a plain {"name": value} file: a fit's best.json
  // ({"parameters": {...}} with provenance) holds values within the fit's own bounds.
  bool allow_out_of_bounds = false;
};

// Reads a JSON object {"name": value, ...} and applies it to `set`. Unknown names, duplicate
// names, non-numeric or non-finite values and values outside the parameter's domain are
// InputErrors naming the file and the parameter; values outside the search bounds too (see
// ParameterFileOptions). A top-level "parameters" object is accepted too (files written by a
// fit carry provenance beside it).
void apply_parameter_json_file(const std::string& path, ParameterSet& set,
                               const ParameterFileOptions& options = {});
// Applies an in-memory JSON object (same rules); `source` names it in errors.
void apply_parameter_json_text(const std::string& text, const std::string& source,
                               ParameterSet& set, const ParameterFileOptions& options = {});
// {"name": value, ...} for every parameter, in registry order, values printed to round-trip.
std::string parameter_set_to_json(const ParameterSet& set);

}  // namespace motoflex
