#pragma once

// Fixtures for the exporter tests: the Nao and the pendulum bench with a "fitted" parameter set
// (every value moved away from its default, so a value that silently fell back to the default
// would show), written as a best.json like `motoflex fit` writes it.

#include <unistd.h>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "motoflex/export/export_input.hpp"
#include "motoflex/model/robot_loader.hpp"
#include "scratch_dir.hpp"

namespace motoflex::testing {

inline std::string robot_dir(const std::string& robot) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/scenarios/robots/" + robot;
}

inline std::shared_ptr<const RobotModel> load_robot(const std::string& robot,
                                                    int flex_sub_bodies = 1) {
  StructureOptions structure;
  structure.flex_sub_bodies = flex_sub_bodies;
  return std::make_shared<const RobotModel>(load_robot_model(robot_dir(robot), structure));
}

// A fresh folder per test, under the process's scratch root (scratch_dir.hpp).
inline std::filesystem::path fresh_export_dir(const std::string& name) {
  return scratch_dir("export_" + name);
}

// Fitted-looking values: the defaults scaled by a factor per parameter (within the bounds).
inline std::map<std::string, double> fitted_values(const RobotModel& model) {
  std::map<std::string, double> out;
  const auto& specs = model.parameters.specs();
  for (std::size_t i = 0; i < specs.size(); ++i) {
    const ParameterSpec& s = specs[i];
    double value = s.default_value * (1.0 + 0.013 * static_cast<double>(i % 7) - 0.03);
    if (s.default_value == 0.0) value = s.lower + 0.1 * (s.upper - s.lower);
    if (s.name.rfind("sensor.", 0) == 0 || s.name.find("encoder") != std::string::npos ||
        s.name.find("stribeck") != std::string::npos ||
        s.name.find("load_friction") != std::string::npos ||
        s.name.find("friction_model") != std::string::npos ||
        s.name.rfind("motor.R_drift", 0) == 0 || s.name.rfind("motor.supply_sag", 0) == 0 ||
        s.name.find(".term_") != std::string::npos || s.name.find("cogging") != std::string::npos ||
        s.name.find("drag_") != std::string::npos ||
        s.name.find("load_saturation") != std::string::npos ||
        s.name.find("torque_saturation") != std::string::npos || s.name == "bench.derivative_s") {
      // Effects the exports drop, or keep in part (the D term's goal-rate feed-forward): keep
      // them neutral.
      value = s.default_value;
    }
    out[s.name] = std::min(std::max(value, s.lower), s.upper);
  }
  return out;
}

// Writes `dir`/best.json in the format of src/fit/fit_runner.cpp.
inline std::string write_best_json(const std::filesystem::path& dir, const RobotModel& model,
                                   const std::map<std::string, double>& values) {
  nlohmann::ordered_json best;
  best["fitness"] = 0.0123;
  best["free"] = {{"joint.*.friction_nm", 0.5}, {"motor.R_ohm", 6.5}};
  nlohmann::ordered_json parameters = nlohmann::ordered_json::object();
  for (const auto& spec : model.parameters.specs()) {
    const auto it = values.find(spec.name);
    parameters[spec.name] = it == values.end() ? spec.default_value : it->second;
  }
  best["parameters"] = parameters;
  best["provenance"] = {
      {"fit", "fits/test.yaml"},
      {"config_hash", "abc123"},
      {"robot", model.name},
      {"date", "2025-01-02T03:04:05Z"},
      {"motoflex_version", "0.1.0"},
      {"run", dir.string()},
      {"data",
       {{{"role", "train"}, {"path", "logs/walk.csv"}, {"hash", "0123abcd"}},
        {{"role", "validation"}, {"path", "logs/kick.csv"}, {"hash", "4567ef"}}}}};
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "best.json").string();
  std::ofstream(path) << best.dump(2) << "\n";
  // The fit's summary beside it, with a 95 % interval for one of the two free parameters.
  std::ofstream(dir / "summary.json")
      << R"({"confidence_intervals": {"motor.R_ohm": {"lower": 6.25, "upper": 6.75}}})"
      << "\n";
  return path;
}

// An ExportInput for `robot` with the fitted values (read through best.json, as the CLI does).
struct Fixture {
  std::shared_ptr<const RobotModel> model;
  std::unique_ptr<ExportInput> input;
};

inline Fixture fitted_fixture(const std::string& robot, const std::string& servo,
                              int flex_sub_bodies = 1) {
  Fixture f;
  f.model = load_robot(robot, flex_sub_bodies);
  const auto dir =
      scratch_root() / ("export_" + robot + "_" + servo + "_" + std::to_string(flex_sub_bodies));
  const std::string best = write_best_json(dir, *f.model, fitted_values(*f.model));
  f.input = std::make_unique<ExportInput>(
      ExportInput{*f.model, ParameterSet(f.model->parameters), servo, {}, 0.001});
  f.input->provenance = read_fitted_parameters(best, f.model->name, f.input->parameters);
  return f;
}

}  // namespace motoflex::testing
