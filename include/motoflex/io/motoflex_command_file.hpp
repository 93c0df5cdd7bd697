#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "motoflex/io/joint_log.hpp"

namespace motoflex {

// Command files of the 2011 MoToFlex program (seed 001; its `config/UncompensatedTarget*.csv`):
// a header row of joint names, then one row of joint angles (rad) per 20 ms (`SOURCE_DT`),
// fields separated by ';', no time column. The ten joints are LHipRoll, LHipPitch, LKneePitch,
// LAnklePitch, LAnkleRoll, RHipRoll, RHipPitch, RKneePitch, RAnklePitch, RAnkleRoll, read by
// their header names (any order); a trailing ';' and "\r\n" line ends are accepted.
//
// Signs (../shared/reference/motoflex_2011.md §2.1): the files use Aldebaran's signs except that
// LHipRoll and LAnkleRoll are mirrored. The original turns a file value into its ODE angle with
// converter[] = +1 for those two and −1 for the others, and its ODE angle is minus the child's
// rotation (body1 of its joints is the parent); so the child turns by −converter · file value:
// +file for the eight others — Aldebaran's sign, the right-hand rule about +x/+y that our URDFs
// use — and −file for LHipRoll and LAnkleRoll. The reference's own check agrees: file LHipRoll
// correlates −0.92 with the left foot's y relative to the torso, while Aldebaran's LHipRoll > 0
// moves the left foot outward (+y); file RHipRoll correlates +0.91 with the right foot's y, as
// Aldebaran's RHipRoll does. Imported angle = file value, negated for LHipRoll and LAnkleRoll.
inline constexpr double kMotoflex2011RowPeriod_s = 0.02;

// The column of `joint` (an Aldebaran name) in the original's order above: LHipRoll 0 …
// RAnkleRoll 9, also the joint's index in the original's robot (its I gain, motoflex_2011.md
// §2.4); nullopt for any other name.
std::optional<std::size_t> motoflex_2011_column(std::string_view joint);

// When each row is commanded.
enum class MotoflexCommandClock {
  // The original program's playback (motoflex_2011.md §2.2): its first frame replaces row 0 by
  // the zero pose, so the command ramps from the zero pose (t = 0) to row 1 at 20 ms and reaches
  // row k at 20·k ms; row 0 is never commanded. The imported log starts with a zero row at t = 0
  // in place of row 0, and a rollout, which builds the robot at the first commanded pose, then
  // starts from the original's straight-legged zero pose too.
  kOriginal,
  // Row k at 20·k ms from row 0 on: the file read as plain 50 Hz samples.
  kPlain,
};

struct MotoflexCommandImportOptions {
  MotoflexCommandClock clock = MotoflexCommandClock::kOriginal;
  std::string robot;  // the sidecar's robot; "" leaves it empty (only for in-memory replays)
};

// True when the first line that is not blank (after a UTF-8 byte order mark) is a ';'-separated
// list of the ten joint names above, i.e. a MoToFlex command file rather than a joint log.
// False for unreadable files (read_joint_log reports those).
bool is_motoflex_command_file(const std::string& path);

// Reads a command file into a joint log (`<joint>.cmd` columns in the file's column order, rad,
// signs converted as above, times by `options.clock`; sidecar rate 50 Hz, motion and origin
// naming the file). Throws InputError(path, line, field, ...) for a missing or empty file, a
// header that is not the ten joint names (unknown, duplicate or missing name), a row with a
// different number of fields, a value that is not a finite number, or fewer than 2 rows.
JointLog import_motoflex_commands(const std::string& path,
                                  const MotoflexCommandImportOptions& options = {});

}  // namespace motoflex
