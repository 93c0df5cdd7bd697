#pragma once

// CLI11 validators for the numbers the commands take, so that `--threads 0`, `--seed -5`,
// `--max-seconds nan` or a seed beyond 64 bits fail at parse time with one line, exit code 2,
// instead of being clamped or ignored.

#include <CLI/CLI.hpp>

namespace motoflex::cli {

// An integer in [1, 1024]: threads or MPI-free parallelism of one machine.
CLI::Validator thread_count();
// An integer in [0, 2^63 - 1], parsed exactly (no wrap-around, no clamping).
CLI::Validator seed_value();
// An integer in [1, 2^63 - 1]: generations, evaluations, rollouts, points.
CLI::Validator positive_count();
// A finite number > 0 (durations in s).
CLI::Validator positive_seconds();
// A finite number >= 0 (settle times in s).
CLI::Validator non_negative_seconds();

}  // namespace motoflex::cli
