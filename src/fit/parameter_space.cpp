#include "motoflex/fit/parameter_space.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace motoflex {

std::vector<std::string> match_parameter_pattern(const ParameterRegistry& registry,
                                                 const std::string& pattern) {
  std::vector<std::string> names;
  for (const auto& spec : registry.specs()) {
    if (parameter_pattern_matches(pattern, spec.name)) names.push_back(spec.name);
  }
  return names;
}

ParameterSpace::ParameterSpace(std::vector<FreeParameter> free, ParameterSet base)
    : free_(std::move(free)), base_(std::move(base)) {
  for (const auto& p : free_) {
    if (p.targets.empty()) throw std::invalid_argument(p.name + ": sets no model parameter");
    if (!(p.lower < p.upper)) throw std::invalid_argument(p.name + ": lower must be below upper");
    if (p.log_scale && !(p.lower > 0.0)) {
      throw std::invalid_argument(p.name + ": a log-scale parameter needs lower > 0");
    }
    std::vector<std::size_t> indices;
    for (const auto& target : p.targets) {
      const auto index = base_.registry().find(target);
      if (!index) throw std::invalid_argument(p.name + ": unknown parameter " + target);
      indices.push_back(*index);
    }
    target_indices_.push_back(std::move(indices));
  }
}

double ParameterSpace::to_model(std::size_t i, double coordinate) const {
  return free_[i].log_scale ? std::exp(coordinate) : coordinate;
}

double ParameterSpace::to_search(std::size_t i, double value) const {
  return free_[i].log_scale ? std::log(value) : value;
}

std::vector<double> ParameterSpace::lower() const {
  std::vector<double> out;
  for (std::size_t i = 0; i < free_.size(); ++i) out.push_back(to_search(i, free_[i].lower));
  return out;
}

std::vector<double> ParameterSpace::upper() const {
  std::vector<double> out;
  for (std::size_t i = 0; i < free_.size(); ++i) out.push_back(to_search(i, free_[i].upper));
  return out;
}

std::vector<double> ParameterSpace::start() const {
  std::vector<double> out;
  for (std::size_t i = 0; i < free_.size(); ++i) out.push_back(to_search(i, free_[i].start));
  return out;
}

ParameterSet ParameterSpace::apply(const std::vector<double>& x) const {
  if (x.size() != free_.size()) throw std::invalid_argument("parameter vector has wrong size");
  ParameterSet set = base_;
  for (std::size_t i = 0; i < free_.size(); ++i) {
    const double value = to_model(i, x[i]);
    for (const std::size_t index : target_indices_[i]) set.set(index, value);
  }
  return set;
}

std::vector<std::pair<std::string, double>> ParameterSpace::values(
    const std::vector<double>& x) const {
  std::vector<std::pair<std::string, double>> out;
  for (std::size_t i = 0; i < free_.size(); ++i) out.emplace_back(free_[i].name, to_model(i, x[i]));
  return out;
}

}  // namespace motoflex
