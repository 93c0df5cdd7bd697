#include "fit_start_from.hpp"

#include <algorithm>
#include <fstream>

#include "motoflex/core/error.hpp"

namespace motoflex::detail {

nlohmann::json read_earlier_run_json(const std::string& path, const std::string& field,
                                     const std::string& unreadable) {
  std::ifstream in(path);
  if (!in) throw InputError(path, 0, field, unreadable);
  try {
    return nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw InputError(path, 0, field, std::string("not JSON: ") + error.what());
  }
}

std::vector<std::pair<std::string, double>> start_from_best(const std::string& best_json,
                                                            std::vector<FreeParameter>& free) {
  const nlohmann::json best =
      read_earlier_run_json(best_json, "--start-from", "cannot read the file");
  const auto number_in = [&](const char* section, const std::string& name, double& value) {
    if (!best.is_object() || !best.contains(section) || !best[section].is_object()) return false;
    const auto found = best[section].find(name);
    if (found == best[section].end() || !found->is_number()) return false;
    value = found->get<double>();
    return true;
  };
  std::vector<std::pair<std::string, double>> incumbent;
  for (FreeParameter& p : free) {
    double value = 0.0;
    if (!number_in("free", p.name, value) &&
        (p.targets.empty() || !number_in("parameters", p.targets.front(), value))) {
      throw InputError(best_json, 0, "free." + p.name,
                       "no value for the free parameter " + p.name +
                           " (neither in \"free\" nor in \"parameters\"; is it a best.json?)");
    }
    p.start = std::clamp(value, p.lower, p.upper);
    incumbent.emplace_back(p.name, p.start);
  }
  return incumbent;
}

}  // namespace motoflex::detail
