#include "fit_hold_identified.hpp"

#include <algorithm>
#include <set>

#include "fit_start_from.hpp"
#include "motoflex/core/error.hpp"

namespace motoflex::detail {
namespace {

// The names of the free parameters the run behind `summary_json` identified (its
// confidence_intervals, "identified": true) or itself held as identified by the run before it
// (held_identified: a chain's later stages keep holding what its first stage identified).
std::set<std::string> identified_names(const std::string& summary_json) {
  const nlohmann::json summary = read_earlier_run_json(
      summary_json, "hold_identified",
      "cannot read the earlier run's summary (it sits beside the --start-from best.json)");
  const auto section = [&](const char* key) {
    return summary.is_object() && summary.contains(key) ? &summary[key] : nullptr;
  };
  const nlohmann::json* intervals = section("confidence_intervals");
  const nlohmann::json* held = section("held_identified");
  if (!(intervals && intervals->is_object()) && !(held && held->is_array())) {
    throw InputError(summary_json, 0, "confidence_intervals",
                     "missing: the earlier run has no intervals (give it `polish: {method: lm, "
                     "covariance: true}`) and held nothing as identified");
  }
  std::set<std::string> names;
  if (intervals && intervals->is_object()) {
    for (const auto& [name, entry] : intervals->items()) {
      if (entry.is_object() && entry.value("identified", false)) names.insert(name);
    }
  }
  if (held && held->is_array()) {
    for (const auto& name : *held) {
      if (name.is_string()) names.insert(name.get<std::string>());
    }
  }
  return names;
}

}  // namespace

std::vector<HeldParameter> hold_identified(const std::string& summary_json,
                                           std::vector<FreeParameter>& free,
                                           std::vector<std::pair<std::string, double>>& incumbent) {
  const std::set<std::string> names = identified_names(summary_json);
  std::vector<HeldParameter> held;
  std::vector<FreeParameter> searched;
  for (FreeParameter& p : free) {
    if (names.count(p.name) > 0) {
      held.push_back({p.name, std::move(p.targets), p.start});
    } else {
      searched.push_back(std::move(p));
    }
  }
  if (searched.empty()) {
    throw InputError(summary_json, 0, "hold_identified",
                     "the earlier run identified every free parameter: nothing is left to search");
  }
  free = std::move(searched);
  incumbent.erase(std::remove_if(incumbent.begin(), incumbent.end(),
                                 [&](const auto& entry) { return names.count(entry.first) > 0; }),
                  incumbent.end());
  return held;
}

}  // namespace motoflex::detail
