#include "motoflex/fit/excitation_check.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>

namespace motoflex {

std::vector<StillJoint> still_joints(const RobotModel& model, const std::vector<FitCase>& cases) {
  const std::size_t n = model.actuators.size();
  std::vector<double> low(n, std::numeric_limits<double>::infinity());
  std::vector<double> high(n, -std::numeric_limits<double>::infinity());
  for (const FitCase& c : cases) {
    if (c.measured_rad.size() % n != 0) continue;
    for (std::size_t k = 0; k < c.measured_rad.size(); ++k) {
      low[k % n] = std::min(low[k % n], c.measured_rad[k]);
      high[k % n] = std::max(high[k % n], c.measured_rad[k]);
    }
  }
  std::vector<StillJoint> out;
  for (std::size_t a = 0; a < n; ++a) {
    if (!(high[a] >= low[a])) continue;  // no frames at all: nothing to judge
    const double range = high[a] - low[a];
    const double still = model.actuators[a].prismatic ? kStillRange_m : kStillRange_rad;
    if (range < still) out.push_back({model.actuators[a].name, range});
  }
  return out;
}

std::vector<std::string> excitation_warnings(const RobotModel& model,
                                             const std::vector<FitCase>& cases) {
  std::vector<std::string> out;
  for (const StillJoint& j : still_joints(model, cases)) {
    const auto it = std::find_if(model.actuators.begin(), model.actuators.end(),
                                 [&](const ActuatorSpec& a) { return a.name == j.joint; });
    const bool slider = it != model.actuators.end() && it->prismatic;
    char line[320];
    std::snprintf(line, sizeof line,
                  "joint '%s' moves only %.3g %s in the training logs (under %g): the excitation "
                  "leaves it nearly still, so its parameters cannot be identified",
                  j.joint.c_str(), j.range, slider ? "m" : "rad",
                  slider ? kStillRange_m : kStillRange_rad);
    out.push_back(line);
  }
  return out;
}

}  // namespace motoflex
