#pragma once

#include <limits>
#include <optional>
#include <string>
#include <vector>

#include "motoflex/core/utc_time.hpp"
#include "motoflex/model/parameters.hpp"
#include "motoflex/model/robot_model.hpp"

namespace motoflex {

// One log a fit read: "train" or "validation", its path and the hash of its CSV (hash_text).
struct ProvenanceDataFile {
  std::string role;
  std::string path;
  std::string hash;
};

// A fitted parameter's value and, when the fit computed one, its 95 % confidence interval
// (summary.json's "confidence_intervals"; NaN when absent).
struct ProvenanceFitted {
  std::string name;  // free parameter (a name or a tied pattern)
  double value = 0.0;
  double lower = std::numeric_limits<double>::quiet_NaN();
  double upper = std::numeric_limits<double>::quiet_NaN();
  // false when the fit flagged it unidentified (its interval spans most of its bounds)
  bool identified = true;
};

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
  std::string run_dir;                       // the fit's run folder
  std::vector<ProvenanceDataFile> data;      // the logs it was fitted and validated on
  std::vector<ProvenanceFitted> fitted;      // "free" values with intervals where known
};

// The provenance as "key: value" lines for the exporters' comments and metadata: exported_by,
// servo, source, fit, run, config_hash, fitness, date, fit_motoflex_version, one "data" line per
// log (role path #hash) and one "fitted" line per free parameter (value [lower, upper]).
std::vector<std::string> provenance_lines(const FitProvenance& provenance,
                                          const std::string& servo);
// The lines as the text of an XML comment ("motoflex provenance:" and one indented line each;
// "--", which XML forbids in comments, written as "- -").
std::string provenance_comment(const FitProvenance& provenance, const std::string& servo);

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
