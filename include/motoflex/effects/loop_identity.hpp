#pragma once

// A loop's output folder remembers what the loop was run with, so that running it again in the
// same folder resumes only the same loop. Each refit keeps its own fit.yaml (a killed loop
// resumes its refits unchanged); without this check a loop started again with another refit
// budget, polish, candidate count or data would silently reuse the old base fit and refits.

#include <string>

#include "motoflex/fit/fit_config.hpp"

namespace motoflex {

// Writes OUT/loop_identity.json for a new loop, or checks the one there: what decides a loop's
// results, the base fit's identity (scenario, robot, logs by content, free parameters, fitness,
// strategy, seed), its budget and the `loop:` section, each hashed (threads and the output path
// are not part of it). When the folder holds a loop of another config or data, its files move to
// OUT/previous-N (nothing is lost, nothing stale is reused) and the returned notice says what
// changed and where they went; "" when the folder was new or holds this loop. Call it while
// holding the folder's FolderLock. Throws InputError naming the file if moving fails.
std::string check_loop_identity(const FitConfig& config, const std::string& out_dir);

}  // namespace motoflex
