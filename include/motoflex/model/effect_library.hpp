#pragma once

// The library of physical effects a model may lack. Each effect is one unit: the model
// parameters that switch it on (names, search bounds, scale), the structure it needs (e.g.
// flexible sub-bodies), which robots it applies to (feet), and the probe that produces its
// residual signature: a small step of its parameters from the current fit, whose effect on the
// simulated encoders is the shape the effect leaves in the residual (see effect_signature.hpp).
// Every hook is already in the simulator with a neutral default, so adding an effect to a fit
// is one line of config: `effects: [stribeck]`.

#include <string>
#include <vector>

#include "motoflex/model/robot_model.hpp"

namespace motoflex {

struct EffectParameter {
  std::string pattern;  // model parameter name or pattern ('*' within one dotted level)
  bool each = true;     // one free value per matched parameter (per joint / gear group)
  bool log_scale = false;
  // Search bounds; NaN = the robot's registry bounds of the first match.
  double lower = std::numeric_limits<double>::quiet_NaN();
  double upper = std::numeric_limits<double>::quiet_NaN();
  // The signature probe moves this parameter by probe_fraction × its search width (in log units
  // for a log-scale parameter), mirrored back into the bounds; 0 = not probed (a shape
  // parameter, e.g. the Stribeck velocity, which keeps its value during the probe).
  double probe_fraction = 0.0;
};

struct Effect {
  std::string name;         // config name, e.g. "stribeck"
  std::string description;  // one line for reports
  std::string signature;    // what its residual looks like, for reports
  std::vector<EffectParameter> parameters;
  bool needs_feet = false;  // ground effects: only robots with foot boxes
  int flex_sub_bodies = 0;  // >= 2: the effect needs links split into sub-bodies
};

// Every effect motoflex knows, in a fixed order.
const std::vector<Effect>& effect_library();
// Throws InputError(source, line, field) naming the known effects when `name` is not one.
const Effect& find_effect(const std::string& name, const std::string& source = "", int line = 0,
                          const std::string& field = "effects");

}  // namespace motoflex
