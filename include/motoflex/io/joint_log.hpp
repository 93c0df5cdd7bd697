#pragma once

#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace motoflex {

// A joint log is a CSV file plus a sidecar YAML next to it with the same stem
// (walk.csv → walk.yaml).
//
// CSV: a UTF-8 byte order mark, '#' comment lines and blank lines (anywhere) are ignored; the
// first other line is the header. Our column names are `time_s`, `<joint>.cmd` (commanded
// angle), `<joint>.meas` (measured angle), `imu.roll`, `imu.pitch`, `supply_v` (the servo supply
// voltage the robot measured, V); joints are numbered in the
// order their first column appears. Without a sidecar `columns:` map, time_s comes first. Each
// following line is one frame of comma-separated fields (spaces around fields are allowed); time
// must strictly increase (the spacing may vary: the physics interpolates the commands linearly
// between frames); the values of our columns are finite numbers. Either every joint has a .cmd
// column or none has, and the same for .meas. Any other column is an extra one: kept as text in
// JointLog::extra_* and otherwise ignored, with one warning naming them all.
//
// Sidecar keys: robot (string, required), rate_hz (number > 0, required: the nominal rate),
// motion (string), units, columns, origin (string, e.g. "motoflex record truth=..." or
// "imported from BAM file X"), parameters (mapping name → number: values the model should use
// for this log, e.g. bench.mass_kg), notes (string). Other keys are errors.
//   columns: {<our name>: <the file's column>, ...}, e.g. {time_s: t, knee.meas: pos_knee}: the
//     file's columns under their own names; time may then be any column.
//   units: rad | deg (every angle column), or per column group
//     {time: s|ms|us|µs|ns, angles: rad|deg, cmd: rad|deg, meas: rad|deg, imu: rad|deg}
//     (cmd/meas/imu override angles). Angles are converted to rad and time to s on reading.
//     An angle beyond ±2π in a group whose unit is not declared is an error (it looks like
//     degrees); declare `units: rad` for multi-turn joints.

struct JointLogMeta {
  std::string robot;          // robot name, e.g. "nao"
  double rate_hz = 0.0;       // nominal frame rate; 0 when there is no sidecar
  std::string motion;         // what the robot did, free text
  std::string units = "rad";  // angle unit of the log in memory (always rad; see units: above)
  std::string origin;         // how the log came to be (recorded, imported, ...)
  std::map<std::string, double> parameters;  // per-log model parameters, e.g. bench.mass_kg
  std::string notes;                         // free text
};

struct JointLog {
  std::vector<std::string> joint_names;  // column order of first appearance
  std::vector<double> time_s;            // one per frame, strictly increasing
  // Frame-major [frame * joints() + joint]; empty when the log has no .cmd columns.
  std::vector<double> commanded_rad;
  // Frame-major like commanded_rad; empty when the log has no .meas columns.
  std::vector<double> measured_rad;
  std::vector<double> imu_roll_rad;   // one per frame; empty when absent
  std::vector<double> imu_pitch_rad;  // one per frame; empty when absent
  // The supply voltage the robot logged (V), one per frame; empty when absent. A servo law with
  // a supply input (servo: bench) drives from it instead of the nominal bench.supply_v.
  std::vector<double> supply_v;
  // The file's columns that are none of ours, in file order, and their fields as written
  // (frame-major [frame * extra_column_names.size() + column]). Not written back by
  // write_joint_log.
  std::vector<std::string> extra_column_names;
  std::vector<std::string> extra_values;
  // What the reader noticed but accepted (e.g. extra columns), one line each, also printed to
  // stderr as "motoflex: warning: ...".
  std::vector<std::string> warnings;
  JointLogMeta meta;

  std::size_t frames() const { return time_s.size(); }
  std::size_t joints() const { return joint_names.size(); }
  bool has_commanded() const { return !commanded_rad.empty(); }
  bool has_measured() const { return !measured_rad.empty(); }
  // Unchecked: frame < frames(), joint < joints(), and the matching has_*() is true.
  double commanded(std::size_t frame, std::size_t joint) const {
    return commanded_rad[frame * joints() + joint];
  }
  double measured(std::size_t frame, std::size_t joint) const {
    return measured_rad[frame * joints() + joint];
  }
  // Index of the joint called `name`, if the log has it.
  std::optional<std::size_t> joint_index(std::string_view name) const {
    for (std::size_t i = 0; i < joint_names.size(); ++i) {
      if (joint_names[i] == name) return i;
    }
    return std::nullopt;
  }
};

// What the caller needs from a log; anything missing is an InputError at read time rather than
// a surprise later.
struct JointLogRequirements {
  bool need_commanded = true;  // every joint must have a .cmd column
  bool need_measured = false;  // every joint must have a .meas column
  bool need_sidecar = false;   // the sidecar YAML must exist (it is always validated if present)
  // If non-empty, each of these joints must be in the log (with .cmd when need_commanded and
  // .meas when need_measured). The log keeps all its joints, in its own order.
  std::vector<std::string> joints;
};

// The sidecar path for a CSV path: the same path with the extension replaced by ".yaml".
std::string joint_log_sidecar_path(const std::string& csv_path);

// Reads a joint log and its sidecar (if present). Every problem with the files throws
// InputError naming the file, the line and the column or key: missing or empty file, bad
// header (no time column, time_s not first without a mapping, duplicate or empty column name,
// missing .cmd/.meas, a required joint missing, a mapped column the header lacks), wrong field
// count, non-numeric or non-finite value, time not strictly increasing, an undeclared angle
// beyond ±2π (with the hint to declare the units), fewer than 2 frames, and any sidecar
// problem. Numbers are parsed locale-independently.
JointLog read_joint_log(const std::string& csv_path, const JointLogRequirements& requirements);

// Writes the CSV and then the sidecar, each atomically (see write_file_atomically). Numbers
// are printed in the shortest form that round-trips, so read_joint_log returns bit-identical
// values. Throws std::invalid_argument if `log` is not something read_joint_log would accept
// (inconsistent sizes, non-finite values, time not strictly increasing, fewer than 2 frames,
// bad joint names, no robot or rate_hz, units other than "rad"), and InputError if a file
// cannot be written.
// significant_digits > 0 rounds the angle columns to that many significant digits (reference
// data: 9 digits keep 1e-9 relative, far below any encoder's resolution, at half the size);
// 0 writes every number so that it reads back bit-identically.
void write_joint_log(const std::string& csv_path, const JointLog& log, int significant_digits = 0);

}  // namespace motoflex
