#include "motoflex/export/json_export.hpp"

#include <cmath>
#include <nlohmann/json.hpp>

#include "motoflex/core/build_info.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/fit/parameter_space.hpp"

namespace motoflex {
namespace {

nlohmann::ordered_json string_or_null(const std::string& text) {
  return text.empty() ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(text);
}

}  // namespace

std::string export_json(const ExportInput& input) {
  const ParameterRegistry& registry = input.parameters.registry();
  std::vector<bool> free(registry.size(), false);
  for (const auto& pattern : input.provenance.free_parameters) {
    for (const auto& name : match_parameter_pattern(registry, pattern)) {
      free[*registry.find(name)] = true;
    }
  }
  nlohmann::ordered_json out;
  out["format"] = "motoflex-parameters";
  out["format_version"] = 1;
  out["robot"] = input.model.name;
  out["servo"] = input.servo;
  nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < registry.size(); ++i) {
    const ParameterSpec& spec = registry.spec(i);
    parameters[spec.name] = {{"value", input.parameters.get(i)},
                             {"unit", spec.unit},
                             {"default", spec.default_value},
                             {"lower", spec.lower},
                             {"upper", spec.upper},
                             {"free", static_cast<bool>(free[i])}};
  }
  out["parameters"] = parameters;

  nlohmann::ordered_json joints = nlohmann::ordered_json::object();
  for (const ActuatorExport& a : export_actuators(input)) {
    joints[a.joint] = {{"group", a.group},
                       {"damping_nm_s_per_rad", a.damping_nm_s_per_rad},
                       {"friction_nm", a.friction_nm},
                       {"effort_nm", a.effort_nm},
                       {"velocity_rad_s", a.velocity_rad_s},
                       {"reduction", a.reduction},
                       {a.prismatic ? "armature_kg" : "armature_kg_m2", a.armature},
                       {"servo_kp_nm_per_rad", a.kp_nm_per_rad},
                       {"servo_kv_nm_s_per_rad", a.kv_nm_s_per_rad}};
  }
  out["joints"] = joints;

  const FitProvenance& p = input.provenance;
  out["provenance"] = {
      {"source", string_or_null(p.source_path)},
      {"fitness", p.fitness ? nlohmann::ordered_json(*p.fitness) : nlohmann::ordered_json(nullptr)},
      {"fit", string_or_null(p.fit_config)},
      {"config_hash", string_or_null(p.config_hash)},
      {"date", string_or_null(p.date)},
      {"motoflex_version", string_or_null(p.motoflex_version)},
      {"run", string_or_null(p.run_dir)},
      {"exported_at", utc_now_iso8601()},
      {"exported_by", std::string("motoflex ") + version()}};
  nlohmann::ordered_json data = nlohmann::ordered_json::array();
  for (const auto& file : p.data) {
    data.push_back({{"role", file.role}, {"path", file.path}, {"hash", file.hash}});
  }
  out["provenance"]["data"] = data;
  nlohmann::ordered_json fitted = nlohmann::ordered_json::object();
  for (const auto& f : p.fitted) {
    fitted[f.name] = {{"value", f.value},
                      {"ci95_lower", std::isfinite(f.lower) ? nlohmann::ordered_json(f.lower)
                                                            : nlohmann::ordered_json(nullptr)},
                      {"ci95_upper", std::isfinite(f.upper) ? nlohmann::ordered_json(f.upper)
                                                            : nlohmann::ordered_json(nullptr)}};
  }
  out["provenance"]["fitted"] = fitted;
  return out.dump(2) + "\n";
}

}  // namespace motoflex
