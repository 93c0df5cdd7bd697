#pragma once

#include "motoflex/fit/fit_config.hpp"

namespace motoflex_es {
class Evaluator;
}

namespace motoflex::cli {

// Runs a fit session on the console: one progress line per generation, SIGINT/SIGTERM end the
// run after the current generation (with its checkpoint), and a closing line. `evaluator` null:
// serial or OpenMP by config.threads. Returns the process exit code.
int run_fit_on_console(FitConfig config, bool resume, motoflex_es::Evaluator* evaluator = nullptr);

}  // namespace motoflex::cli
