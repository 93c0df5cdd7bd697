// motoflex.FitSpec: every option of a fit YAML as attributes, read from a file or built in
// Python (`FitSpec()`, then scenario_path, train_data, free, ...). is_valid() checks what can
// be checked without reading files; fit() checks the rest and names the field.

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "json_python.hpp"
#include "motoflex/fit/fit_config.hpp"
#include "motoflex/fit/fit_spec.hpp"

namespace py = pybind11;

namespace motoflex::python {
namespace {

std::vector<std::string> paths_of(const std::vector<LogSource>& sources) {
  std::vector<std::string> paths;
  for (const auto& source : sources) paths.push_back(source.path);
  return paths;
}

std::vector<LogSource> sources_of(const std::vector<std::string>& paths) {
  std::vector<LogSource> sources;
  for (const auto& path : paths) sources.push_back({path, {}});
  return sources;
}

void bind_strategy(py::module_& m) {
  py::class_<StrategyConfig>(m, "StrategyConfig", "The `strategy:` section of a fit YAML.")
      .def(py::init<>())
      .def_readwrite("kind", &StrategyConfig::kind, "mu_plus_lambda | cma_es | nlopt")
      .def_readwrite("mu", &StrategyConfig::mu)
      .def_readwrite("lambda_", &StrategyConfig::lambda)
      .def_readwrite("kappa", &StrategyConfig::kappa)
      .def_readwrite("rho", &StrategyConfig::rho)
      .def_readwrite("object_recombination", &StrategyConfig::object_recombination)
      .def_readwrite("step_recombination", &StrategyConfig::step_recombination)
      .def_readwrite("initial_step", &StrategyConfig::initial_step)
      .def_readwrite("sigma", &StrategyConfig::sigma)
      .def_readwrite("population", &StrategyConfig::population)
      .def_readwrite("restarts", &StrategyConfig::restarts)
      .def_readwrite("algorithm", &StrategyConfig::algorithm)
      .def_readwrite("polish", &StrategyConfig::polish)
      .def_readwrite("polish_evaluations", &StrategyConfig::polish_evaluations)
      .def("to_dict", [](const StrategyConfig& s) { return json_to_python(strategy_to_json(s)); });
  py::class_<PolishSpec>(m, "PolishSpec",
                         "The `polish:` section: Levenberg-Marquardt after the strategy "
                         "(method 'lm'), and the covariance / 95 % intervals.")
      .def(py::init<>())
      .def_readwrite("method", &PolishSpec::method)
      .def_readwrite("max_iterations", &PolishSpec::max_iterations)
      .def_readwrite("jacobian_step", &PolishSpec::jacobian_step)
      .def_readwrite("covariance", &PolishSpec::covariance);
  py::class_<FitBudget>(m, "FitBudget", "The `budget:` section (0 = no limit).")
      .def(py::init<>())
      .def_readwrite("max_generations", &FitBudget::max_generations)
      .def_readwrite("max_evaluations", &FitBudget::max_evaluations)
      .def_readwrite("max_seconds", &FitBudget::max_seconds);
}

void bind_free_parameter(py::module_& m) {
  py::class_<FreeParameterSpec>(m, "FreeParameter",
                                "One entry of `free:`: a name or pattern, optional bounds and "
                                "start, log-scale search, one value per match (each).")
      .def(py::init([](const std::string& pattern, std::optional<double> lower,
                       std::optional<double> upper, std::optional<double> start, bool log_scale,
                       bool each) {
             FreeParameterSpec spec;
             spec.pattern = pattern;
             spec.lower = lower;
             spec.upper = upper;
             spec.start = start;
             spec.log_scale = log_scale;
             spec.each = each;
             return spec;
           }),
           py::arg("pattern"), py::kw_only(), py::arg("lower") = py::none(),
           py::arg("upper") = py::none(), py::arg("start") = py::none(),
           py::arg("log_scale") = false, py::arg("each") = false)
      .def_readwrite("pattern", &FreeParameterSpec::pattern)
      .def_readwrite("lower", &FreeParameterSpec::lower)
      .def_readwrite("upper", &FreeParameterSpec::upper)
      .def_readwrite("start", &FreeParameterSpec::start)
      .def_readwrite("log_scale", &FreeParameterSpec::log_scale)
      .def_readwrite("each", &FreeParameterSpec::each)
      .def("__repr__",
           [](const FreeParameterSpec& f) { return "<motoflex.FreeParameter " + f.pattern + ">"; });
}

}  // namespace

void bind_fit_spec(py::module_& m) {
  bind_strategy(m);
  bind_free_parameter(m);
  py::class_<FitSpec>(m, "FitSpec", "Every option of a fit YAML (see README: fit configs).")
      .def(py::init<>())
      .def_static(
          "load",
          [](const std::string& path, std::optional<int> threads, std::optional<std::uint64_t> seed,
             std::optional<std::uint64_t> max_generations, std::optional<std::string> out) {
            FitOverrides overrides;
            overrides.threads = threads;
            overrides.seed = seed;
            overrides.max_generations = max_generations;
            overrides.out = out;
            return load_fit_spec(path, overrides);
          },
          py::arg("path"), py::kw_only(), py::arg("threads") = py::none(),
          py::arg("seed") = py::none(), py::arg("max_generations") = py::none(),
          py::arg("out") = py::none(), "Reads a fit YAML (every problem at once in the error).")
      .def_readwrite("path", &FitSpec::path)
      .def_readwrite("name", &FitSpec::name)
      .def_readwrite("scenario_path", &FitSpec::scenario_path)
      .def_property(
          "train_data", [](const FitSpec& s) { return paths_of(s.train_data); },
          [](FitSpec& s, const std::vector<std::string>& p) { s.train_data = sources_of(p); })
      .def_property(
          "validation_data", [](const FitSpec& s) { return paths_of(s.validation_data); },
          [](FitSpec& s, const std::vector<std::string>& p) { s.validation_data = sources_of(p); })
      .def_readwrite("free", &FitSpec::free)
      .def_property(
          "fixed", [](const FitSpec& s) { return s.fixed; },
          [](FitSpec& s, const std::vector<std::pair<std::string, double>>& values) {
            s.fixed = values;
            s.fixed_where.assign(values.size(), {});
          })
      .def_property(
          "effects", [](const FitSpec& s) { return s.effects; },
          [](FitSpec& s, const std::vector<std::string>& effects) {
            s.effects = effects;
            s.effects_where.assign(effects.size(), {});
          })
      .def_readwrite("fitness_m", &FitSpec::fitness_m)
      .def_readwrite("fitness_settle_s", &FitSpec::fitness_settle_s)
      .def_readwrite("joint_weights", &FitSpec::joint_weights)
      .def_readwrite("imu_weight", &FitSpec::imu_weight)
      .def_readwrite("window_s", &FitSpec::window_s)
      .def_readwrite("absolute_error", &FitSpec::absolute_error)
      .def_readwrite("early_termination", &FitSpec::early_termination)
      .def_readwrite("strategy", &FitSpec::strategy)
      .def_readwrite("budget", &FitSpec::budget)
      .def_readwrite("polish", &FitSpec::polish)
      .def_readwrite("threads", &FitSpec::threads)
      .def_readwrite("seed", &FitSpec::seed)
      .def_readwrite("out_dir", &FitSpec::out_dir)
      .def(
          "is_valid",
          [](const FitSpec& s) {
            std::string error;
            const bool valid = s.is_valid(&error);
            return py::make_tuple(valid, error);
          },
          "(True, '') or (False, what is wrong), without reading any file.")
      .def(
          "to_dict", [](const FitSpec& s) { return json_to_python(fit_spec_to_json(s)); },
          "The spec as fit.yaml would read it back (paths absolute).")
      .def("__repr__", [](const FitSpec& s) { return "<motoflex.FitSpec " + s.name + ">"; });
}

}  // namespace motoflex::python
