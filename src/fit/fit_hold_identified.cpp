#include "fit_hold_identified.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "motoflex/core/error.hpp"

namespace motoflex::detail {
namespace {

// The names of the free parameters the run behind `summary_path` identified (its
// confidence_intervals, "identified": true) or itself held as identified by the run before it
// (held_identified: a chain's later stages keep holding what its first stage identified).
std::vector<std::string> identified_names(const std::string& summary_path) {
  std::ifstream in(summary_path);
  if (!in) {
    throw InputError(summary_path, 0, "hold_identified",
                     "cannot read the earlier run's summary (it sits beside the --start-from "
                     "best.json)");
  }
  nlohmann::json summary;
  try {
    summary = nlohmann::json::parse(in);
  } catch (const nlohmann::json::exception& error) {
    throw InputError(summary_path, 0, "hold_identified", std::string("not JSON: ") + error.what());
  }
  const bool has_intervals = summary.is_object() && summary.contains("confidence_intervals") &&
                             summary["confidence_intervals"].is_object();
  const bool has_held = summary.is_object() && summary.contains("held_identified") &&
                        summary["held_identified"].is_array();
  if (!has_intervals && !has_held) {
    throw InputError(summary_path, 0, "confidence_intervals",
                     "missing: the earlier run has no intervals (give it `polish: {method: lm, "
                     "covariance: true}`) and held nothing as identified");
  }
  std::vector<std::string> names;
  if (has_intervals) {
    for (const auto& [name, entry] : summary["confidence_intervals"].items()) {
      if (entry.is_object() && entry.value("identified", false) == true) names.push_back(name);
    }
  }
  if (has_held) {
    for (const auto& name : summary["held_identified"]) {
      if (name.is_string()) names.push_back(name.get<std::string>());
    }
  }
  return names;
}

}  // namespace

std::vector<HeldParameter> hold_identified(const std::string& best_json,
                                           std::vector<FreeParameter>& free,
                                           std::vector<std::pair<std::string, double>>& incumbent) {
  const std::string summary_path =
      (std::filesystem::path(best_json).parent_path() / "summary.json").string();
  const std::vector<std::string> names = identified_names(summary_path);
  const auto identified = [&](const FreeParameter& p) {
    return std::find(names.begin(), names.end(), p.name) != names.end();
  };
  std::vector<HeldParameter> held;
  for (const FreeParameter& p : free) {
    if (identified(p)) held.push_back({p.name, p.targets, p.start});
  }
  if (held.size() == free.size()) {
    throw InputError(summary_path, 0, "hold_identified",
                     "the earlier run identified every free parameter: nothing is left to search");
  }
  free.erase(std::remove_if(free.begin(), free.end(), identified), free.end());
  incumbent.erase(std::remove_if(incumbent.begin(), incumbent.end(),
                                 [&](const auto& entry) {
                                   return std::any_of(held.begin(), held.end(),
                                                      [&](const HeldParameter& h) {
                                                        return h.name == entry.first;
                                                      });
                                 }),
                  incumbent.end());
  return held;
}

}  // namespace motoflex::detail
