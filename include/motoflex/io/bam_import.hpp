#pragma once

#include <optional>
#include <string>
#include <vector>

#include "motoflex/io/joint_log.hpp"

namespace motoflex {

// Import of the pendulum-bench logs of BAM (Rhoban/bam, "Better Actuator Models") into our
// joint-log format, for the `servo_pendulum` robot (joint `pendulum`). Format of the BAM files:
// shared/data/bam/README.md and the README of each actuator folder.
//
// A BAM trajectory log is a JSON object with `mass` [kg], `length` [m], `entries` (list of
// {timestamp [s], position [rad], goal_position [rad], torque_enable (bool, optional), ...}) and
// optionally `kp`, `vin` [V], `motor`, `trajectory`, `dt` [s] (processed files only). The
// imported log has one frame per entry: time_s = timestamp exactly as logged (raw files keep
// their irregular clock and do not start at 0), pendulum.cmd = goal_position, pendulum.meas =
// position. Other entry fields (speed, load, input_volts, temp) are dropped.
//
// Sidecar: robot servo_pendulum; rate_hz = 1/dt for processed files, the mean rate
// (entries − 1)/(last − first timestamp) for raw files; motion = `trajectory`; origin =
// "imported from BAM <display path>"; parameters bench.mass_kg, bench.length_m, bench.kp (the
// log's kp), bench.supply_v (the log's vin) and, when BAM has a voltage-servo model for the
// log's motor (xl330, xl320, mx64, mx106), bench.error_gain and bench.max_duty; notes say what
// kind of file it was, when the torque was released and which values were left out and why.

struct BamImport {
  JointLog log;
  // Timestamp [s] of the first entry with torque_enable false (the servo's H-bridge released,
  // e.g. lift_and_drop after 2 s); the samples after it are kept, their goal_position is what
  // the recorder logged but the servo no longer followed it. Empty when torque stays on.
  std::optional<double> torque_off_s;
  std::string motor;       // the log's `motor` field, "" when absent
  bool processed = false;  // a processed file (resampled on a uniform `dt` grid by bam/process.py)
};

// Reads one BAM trajectory log. `display_path` is the name used in errors and in the sidecar's
// origin (e.g. the path relative to the imported folder). Throws InputError(display_path, line,
// field, ...) — line is 0 except for JSON syntax errors — when the file cannot be read, is not
// JSON, or is not a usable trajectory log: a missing key (entries, mass, length, and timestamp,
// position, goal_position in every entry), a value of the wrong type, a NaN or infinite
// number (Python's json writes bare NaN/Infinity; they are reported as such, not as syntax
// errors), mass/length/vin/dt not > 0, fewer than 2 entries, a timestamp that does not strictly
// increase (equal timestamps are an error, not silently dropped: every logged sample is kept or
// the import fails), a processed file whose timestamps are off the dt grid by more than 1 µs,
// and torque_enable going back to true after a release. A file that is recognisably not a
// trajectory log (a BAM calibration table, a 2R arm log, ...) is reported as a missing
// `entries` key or as unsupported, with what it looks like.
BamImport import_bam_file(const std::string& path, const std::string& display_path);

// One file found below a folder by import_bam_directory.
struct BamDirectoryItem {
  std::string relative_path;        // below the folder, '/'-separated, e.g. xl330/raw/a.json
  std::string output_stem;          // bam_output_stem(relative_path)
  std::optional<BamImport> import;  // empty when the file was skipped
  std::string skip_reason;          // why it was skipped (empty when imported)
};

// The output name (without extension) for a file below the imported folder: the relative path
// with '/' replaced by '_' and a trailing ".json" removed (xl330/raw/2026-01-15_10h28m10.json →
// xl330_raw_2026-01-15_10h28m10).
std::string bam_output_stem(const std::string& relative_path);

// Imports every BAM trajectory log below `dir` (recursively, in sorted path order) and lists
// every other file with the reason it was skipped: files not ending in .json, JSON files
// that are not single-axis trajectory logs (no `entries` list, e.g. the mx64/mx106 calibration
// tables or the free-pendulum friction log; 2R arm logs), and the raw copy of a recording whose
// processed copy is also below `dir` (BAM keeps both under the same file name, e.g. raw/ and
// processed/; same motor, kp and trajectory): the processed one is imported, as BAM fits on it,
// so that no recording counts twice in a fit or a validation. Everything is imported before
// anything is returned, so a bad trajectory log fails the whole call: a file that has
// `entries` but is broken, or a .json file that is not valid JSON (it may be a truncated log),
// throws InputError naming it as `dir`/relative path, as do `dir` not being a folder and two
// files mapping to the same output stem. The sidecar origin names the relative path.
std::vector<BamDirectoryItem> import_bam_directory(const std::string& dir);

}  // namespace motoflex
