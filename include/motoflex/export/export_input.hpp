#pragma once

#include <optional>
#include <string>
#include <vector>

#include "motoflex/core/utc_time.hpp"
#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// Where a fitted parameter set came from: best.json's "fitness", "free" and "provenance"
// (written by `motoflex fit`, src/fit/fit_runner.cpp). Fields a file does not have stay empty.
struct FitProvenance {
  std::string source_path;                   // the file the parameters were read from
  std::optional<double> fitness;             // best fitness of the fit (eq. 2 of seed 001)
  std::string fit_config;                    // path of the fit YAML
  std::string config_hash;                   // hash of the fit config
  std::string robot;                         // robot name the fit used
  std::string date;                          // when the fit wrote best.json (ISO 8601, UTC)
  std::string motoflex_version;              // motoflex version that ran the fit
  std::vector<std::string> free_parameters;  // what the optimiser searched ("free"); may be
                                             // patterns such as "joint.*.friction_nm" (ties)
};

// Everything an exporter reads: the robot as motoflex simulates it (the structure options of
// the model decide lumped bodies, universal joints and flexible sub-bodies), a value for every
// parameter, the servo law the values belong to, and their provenance.
struct ExportInput {
  const RobotModel& model;
  ParameterSet parameters;
  // The servo law the values belong to (empty: each joint's own, actuator_servo_name).
  std::string servo = "motoflex";
  FitProvenance provenance;
  double dt_s = 0.001;  // physics step the parameters were fitted at (MJCF/SDF time step)
};

// Applies a fit result on top of `parameters` (normally the robot's defaults) and returns its
// provenance. Accepts best.json ({"fitness", "free", "parameters", "provenance"}) and plain
// parameter files ({"name": value, ...}). Throws InputError naming the file and the field for
// invalid JSON, unknown parameter names, non-numeric values and a provenance robot that is not
// `parameters`' robot (`robot_name`).
FitProvenance read_fitted_parameters(const std::string& path, const std::string& robot_name,
                                     ParameterSet& parameters);

}  // namespace motoflex
