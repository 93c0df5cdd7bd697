#include "motoflex/report/figure_data.hpp"

#include <cmath>
#include <filesystem>

#include "json_numbers.hpp"
#include "motoflex/core/error.hpp"

namespace motoflex::report {

nlohmann::json convergence_json(const std::vector<GenerationRow>& rows) {
  if (rows.empty()) return nullptr;
  nlohmann::json out = {{"generation", nlohmann::json::array()},
                        {"evaluations", nlohmann::json::array()},
                        {"best", nlohmann::json::array()},
                        {"median", nlohmann::json::array()}};
  for (const auto& row : rows) {
    out["generation"].push_back(row.generation);
    out["evaluations"].push_back(row.evaluations);
    out["best"].push_back(detail::number_json(row.best));
    out["median"].push_back(detail::number_json(row.median));
  }
  return out;
}

nlohmann::json correlation_json(const NamedMatrix& correlation) {
  if (correlation.empty()) return nullptr;
  nlohmann::json matrix = nlohmann::json::array();
  for (const auto& row : correlation.values) {
    nlohmann::json values = nlohmann::json::array();
    for (const double v : row) {
      values.push_back(std::isfinite(v) ? nlohmann::json(std::round(v * 1e4) / 1e4) : nullptr);
    }
    matrix.push_back(std::move(values));
  }
  return {{"names", correlation.names}, {"matrix", std::move(matrix)}};
}

std::vector<LogComparison> load_log_comparisons(const RunRecord& record, std::size_t max_points,
                                                std::vector<std::string>& notes) {
  std::vector<LogComparison> out;
  const JointLogRequirements anything{false, false, false, {}};
  for (const LogFiles& files : record.logs) {
    const std::string label = files.set + " log " + files.name;
    if (files.simulated_path.empty()) {
      notes.push_back(label + ": no simulated log of the best parameters in the run dir");
      continue;
    }
    if (files.measured_path.empty()) {
      notes.push_back(label + ": the measured log is unknown");
      continue;
    }
    if (!std::filesystem::exists(files.measured_path)) {
      notes.push_back(label + ": the measured log " + files.measured_path + " is not there");
      continue;
    }
    try {
      const JointLog measured = read_joint_log(files.measured_path, anything);
      const JointLog simulated = read_joint_log(files.simulated_path, anything);
      LogComparison comparison = compare_logs(measured, simulated, max_points);
      comparison.name = files.name;
      comparison.set = files.set;
      if (comparison.channels.empty()) {
        notes.push_back(label + ": no joint both measured and simulated");
        continue;
      }
      out.push_back(std::move(comparison));
    } catch (const InputError& error) {
      notes.push_back(label + ": " + error.what());
    }
  }
  return out;
}

}  // namespace motoflex::report
