// motoflex.Scenario and motoflex.simulate: load a scenario (or a truth file's recording) as
// `motoflex simulate` does, replay it with any parameter values, get NumPy arrays back.
//
//   s = motoflex.Scenario("scenarios/nao_default.yaml", duration_s=2.0)
//   r = s.simulate({"motor.R_ohm": 6.5})      # the GIL is released while ODE runs
//   r["measured_rad"].shape                    # (frames, joints)

#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <tuple>
#include <utility>

#include "bindings.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/scenario/truth_file.hpp"
#include "motoflex/sim/rollout.hpp"
#include "numpy_arrays.hpp"

namespace py = pybind11;

namespace motoflex::python {
namespace {

struct ScenarioArgs {
  std::optional<std::string> params;  // parameter JSON file
  std::optional<std::string> motion;  // replay this log's commands
  std::optional<std::string> servo;
  std::optional<std::string> solver;  // "step" | "sparse" | "quick"
  std::optional<double> duration_s;
  std::string recording;  // a truth file's recording ("" = its first)
};

Scenario load(const std::string& path, const ScenarioArgs& args) {
  ScenarioOverrides overrides;
  overrides.parameters_json = args.params;
  overrides.motion_log = args.motion;
  overrides.servo = args.servo;
  overrides.duration_s = args.duration_s;
  if (args.solver) {
    overrides.solver = parse_step_solver(*args.solver);
    if (!overrides.solver) throw InputError("", 0, "solver", kStepSolverChoices);
  }
  return load_scenario_or_truth(path, overrides, args.recording);
}

// `parameters` with a dict's values on top; unknown names and non-numbers are InputErrors.
ParameterSet with_values(const Scenario& scenario, const std::map<std::string, double>& values) {
  ParameterSet set = scenario.parameters;
  for (const auto& [name, value] : values) {
    if (!set.registry().contains(name)) {
      const std::string close = set.registry().closest_name(name);
      throw InputError("", 0, name,
                       "not a parameter of robot " + scenario.model->name +
                           (close.empty() ? "" : " (did you mean " + close + "?)"));
    }
    if (!std::isfinite(value)) throw InputError("", 0, name, "must be finite");
    set.set(name, value);
  }
  return set;
}

py::dict result_dict(const RolloutResult& r) {
  const std::size_t joints = r.joints();
  const std::size_t frames = r.frames_completed;
  const std::size_t recorded = r.torso_position_m.size() / 3;
  py::dict out;
  out["joint_names"] = r.joint_names;
  out["time_s"] = vector_array({r.time_s.begin(), r.time_s.begin() + frames});
  out["commanded_rad"] = matrix_array(r.commanded_rad, frames, joints);
  out["measured_rad"] = matrix_array(r.measured_rad, frames, joints);
  if (!r.joint_torque_nm.empty()) {
    out["joint_torque_nm"] = matrix_array(r.joint_torque_nm, frames, joints);
  }
  out["imu_roll_rad"] = vector_array({r.imu_roll_rad.begin(), r.imu_roll_rad.begin() + frames});
  out["imu_pitch_rad"] = vector_array({r.imu_pitch_rad.begin(), r.imu_pitch_rad.begin() + frames});
  out["torso_position_m"] = matrix_array(r.torso_position_m, frames, 3);
  const std::size_t feet = recorded == 0 ? 0 : r.foot_force_z_n.size() / recorded;
  out["foot_force_z_n"] = matrix_array(r.foot_force_z_n, frames, feet);
  out["frames_requested"] = r.frames_requested;
  out["frames_completed"] = r.frames_completed;
  out["end"] = std::string(to_string(r.end));
  out["end_time_s"] = r.end_time_s;
  out["end_detail"] = r.end_detail;
  out["physics_steps"] = r.physics_steps;
  return out;
}

py::dict simulate(const Scenario& scenario, const std::map<std::string, double>& values,
                  bool record_torques) {
  const ParameterSet parameters = with_values(scenario, values);
  RolloutOptions options = scenario.rollout;
  options.record_torques = options.record_torques || record_torques;
  RolloutResult result;
  {
    py::gil_scoped_release release;
    result = run_rollout(*scenario.model, parameters, scenario.commands, options);
  }
  if (result.end == RolloutEnd::kModelError) {
    throw ModelError("cannot simulate " + scenario.path + ": " + result.end_detail);
  }
  return result_dict(result);
}

py::dict parameter_table(const Scenario& scenario) {
  py::dict out;
  const ParameterRegistry& registry = scenario.parameters.registry();
  for (std::size_t i = 0; i < registry.size(); ++i) {
    const ParameterSpec& spec = registry.spec(i);
    out[py::str(spec.name)] =
        py::make_tuple(scenario.parameters.get(i), spec.lower, spec.upper, spec.unit);
  }
  return out;
}

py::dict parameter_values(const Scenario& scenario) {
  py::dict out;
  const ParameterRegistry& registry = scenario.parameters.registry();
  for (std::size_t i = 0; i < registry.size(); ++i) {
    out[py::str(registry.spec(i).name)] = scenario.parameters.get(i);
  }
  return out;
}

std::vector<std::string> joint_names(const Scenario& scenario) {
  std::vector<std::string> names;
  for (const auto& actuator : scenario.model->actuators) names.push_back(actuator.name);
  return names;
}

}  // namespace

void bind_simulate(py::module_& m) {
  py::class_<Scenario>(m, "Scenario",
                       "A robot, its physics and a motion, loaded from a scenario YAML or a "
                       "truth file's recording exactly as `motoflex simulate` loads it.")
      .def(py::init([](const std::string& path, std::optional<std::string> params,
                       std::optional<std::string> motion, std::optional<std::string> servo,
                       std::optional<std::string> solver, std::optional<double> duration_s,
                       const std::string& recording) {
             return load(path, {params, motion, servo, solver, duration_s, recording});
           }),
           py::arg("path"), py::kw_only(), py::arg("params") = py::none(),
           py::arg("motion") = py::none(), py::arg("servo") = py::none(),
           py::arg("solver") = py::none(), py::arg("duration_s") = py::none(),
           py::arg("recording") = "")
      .def_readonly("path", &Scenario::path)
      .def_readonly("name", &Scenario::name)
      .def_property_readonly("robot", [](const Scenario& s) { return s.model->name; })
      .def_property_readonly("servo", [](const Scenario& s) { return s.rollout.servo; })
      .def_property_readonly("joint_names", &joint_names)
      .def_property_readonly("duration_s",
                             [](const Scenario& s) { return s.commands.duration_s(); })
      .def_readonly("log_rate_hz", &Scenario::log_rate_hz)
      .def_readonly("motion", &Scenario::motion_description)
      .def_property_readonly("parameters", &parameter_values,
                             "name -> value the scenario simulates with (a copy)")
      .def_property_readonly("parameter_table", &parameter_table,
                             "name -> (value, lower bound, upper bound, unit)")
      .def("simulate", &simulate, py::arg("params") = std::map<std::string, double>{},
           py::arg("record_torques") = false,
           "Replays the scenario's commands with `params` (name -> value) on top of its "
           "parameters; returns a dict of NumPy arrays (rows: frames simulated).")
      .def("__repr__", [](const Scenario& s) {
        return "<motoflex.Scenario " + s.name + ": robot " + s.model->name + ", servo " +
               s.rollout.servo + ", " + std::to_string(s.commands.frames()) + " frames>";
      });

  m.def(
      "simulate",
      [](const std::string& path, const std::map<std::string, double>& params,
         std::optional<std::string> params_file, std::optional<std::string> motion,
         std::optional<std::string> servo, std::optional<double> duration_s, bool record_torques) {
        const Scenario scenario = load(path, {params_file, motion, servo, {}, duration_s, ""});
        return simulate(scenario, params, record_torques);
      },
      py::arg("path"), py::arg("params") = std::map<std::string, double>{}, py::kw_only(),
      py::arg("params_file") = py::none(), py::arg("motion") = py::none(),
      py::arg("servo") = py::none(), py::arg("duration_s") = py::none(),
      py::arg("record_torques") = false,
      "Loads a scenario and simulates it once (see Scenario.simulate).");
}

}  // namespace motoflex::python
