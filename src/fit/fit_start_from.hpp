#pragma once

// Internal to resolve_fit_config: `--start-from BEST.json`, chaining a fit on an earlier run
// (e.g. a fit on the logs' first seconds, then on the whole logs).

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "motoflex/fit/parameter_space.hpp"

namespace motoflex::detail {

// A JSON file the earlier run wrote (its best.json, the summary.json beside it). Throws
// InputError(path, 0, field, ...) when it cannot be read (`unreadable` says what it is) or is not
// JSON.
nlohmann::json read_earlier_run_json(const std::string& path, const std::string& field,
                                     const std::string& unreadable);

// Sets each free parameter's start to its value in the run's best.json ("free" by the free
// parameter's name, else "parameters" by its first target: a parameter that run held), clamped
// to the parameter's bounds, and returns those values as the incumbent (name → value). Throws
// InputError naming the file and the parameter when the file is unreadable or lacks a value.
std::vector<std::pair<std::string, double>> start_from_best(const std::string& best_json,
                                                            std::vector<FreeParameter>& free);

}  // namespace motoflex::detail
