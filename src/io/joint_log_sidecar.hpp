#pragma once

// Internal to the joint-log reader: the sidecar YAML of a log, with what it says about the CSV
// itself (which file column is which of ours, and the units of the time and angle columns), so
// that logs from any recorder can be read as they come.

#include <map>
#include <string>
#include <vector>

#include "motoflex/io/joint_log.hpp"

namespace motoflex::detail {

enum class AngleUnit { kUndeclared, kRad, kDeg };

// The units the sidecar declares for each column group.
struct ColumnUnits {
  double seconds_per_time_unit = 1.0;  // s 1, ms 1e-3, us/µs 1e-6, ns 1e-9
  AngleUnit cmd = AngleUnit::kUndeclared;
  AngleUnit meas = AngleUnit::kUndeclared;
  AngleUnit imu = AngleUnit::kUndeclared;
};

// One `columns:` entry: our column name (time_s, <joint>.cmd, <joint>.meas, imu.roll,
// imu.pitch) read from the file's column `file_column`.
struct ColumnMapping {
  std::string ours;
  std::string file_column;
  int line = 0;  // of the entry in the sidecar
};

struct Sidecar {
  std::string path;
  int rate_line = 0;  // line of rate_hz (errors about the rate point at it)
  JointLogMeta meta;  // meta.units stays "rad": the log in memory is always rad and s
  ColumnUnits units;
  std::vector<ColumnMapping> columns;  // in sidecar order; empty = the header uses our names
};

// Whether `name` is one of our column names (time_s, <joint>.cmd, <joint>.meas, imu.roll,
// imu.pitch).
bool is_our_column_name(const std::string& name);

// Reads a sidecar. Throws InputError(path, line, field) for anything malformed: unknown keys,
// missing robot/rate_hz, a unit that is not rad|deg (angles) or s|ms|us|µs|ns (time), a
// `columns:` key that is not one of our names or a value that is not a string, two of our
// names mapped to one file column, non-numeric parameters.
Sidecar read_joint_log_sidecar(const std::string& path);

}  // namespace motoflex::detail
