#include "motoflex/effects/refit_start_scan.hpp"

#include <cmath>

namespace motoflex::detail {
namespace {

const FreeParameter* free_parameter(const ParameterSpace& space, const std::string& name) {
  for (const FreeParameter& p : space.free_parameters()) {
    if (p.name == name || (!p.targets.empty() && p.targets.front() == name)) return &p;
  }
  return nullptr;
}

}  // namespace

void scan_effect_start(
    const ParameterSpace& space, std::size_t points,
    const std::function<double(const std::vector<std::pair<std::string, double>>&)>& fitness,
    std::vector<std::pair<std::string, double>>& estimate, double& best_fitness) {
  if (points < 3) return;
  for (std::size_t i = 0; i < estimate.size(); ++i) {
    const FreeParameter* p = free_parameter(space, estimate[i].first);
    if (p == nullptr) continue;
    const double lo = p->log_scale ? std::log(p->lower) : p->lower;
    const double hi = p->log_scale ? std::log(p->upper) : p->upper;
    for (std::size_t j = 0; j < points; ++j) {
      const double t = lo + (hi - lo) * static_cast<double>(j) / static_cast<double>(points - 1);
      auto trial = estimate;
      trial[i].second = p->log_scale ? std::exp(t) : t;
      const double f = fitness(trial);
      if (f < best_fitness) {
        best_fitness = f;
        estimate = std::move(trial);
      }
    }
  }
}

}  // namespace motoflex::detail
