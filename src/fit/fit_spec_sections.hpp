#pragma once

// Internal to the fit spec reader: the readers of fit.yaml's `strategy:`, `budget:`, `polish:` and
// `loop:` sections (also the refit section of `loop:`).

#include "motoflex/fit/fit_spec.hpp"
#include "motoflex/io/yaml_reader.hpp"

namespace motoflex {

StrategyConfig read_strategy(const YamlValue& node);
FitBudget read_budget(const YamlValue& budget);
PolishSpec read_polish(const YamlValue& node);
LoopOptions read_loop(const YamlValue& node);

}  // namespace motoflex
