#include "excitation_scenario_motion.hpp"

#include <limits>
#include <stdexcept>

#include "motoflex/motion/excitation.hpp"

namespace motoflex::detail {

std::optional<CommandTrajectory> excitation_motion_from_yaml(const YamlValue& motion,
                                                             const RobotModel& model) {
  const auto node = motion.find("excitation");
  if (!node) return std::nullopt;
  node->require_keys_within(
      {"kind", "amplitude_rad", "f0_hz", "f1_hz", "duration_s", "rate_hz", "ramp_s"});
  ExcitationParams params;
  const std::string kind = node->get_string("kind", "multisine");
  if (kind == "chirp") {
    params.kind = ExcitationParams::Kind::kChirp;
  } else if (kind != "multisine") {
    node->at("kind").fail("expected multisine or chirp");
  }
  params.amplitude_rad = node->get_double("amplitude_rad", params.amplitude_rad);
  params.f0_hz = node->get_double("f0_hz", params.f0_hz);
  params.f1_hz = node->get_double("f1_hz", params.f1_hz);
  params.duration_s = node->get_double("duration_s", params.duration_s);
  params.rate_hz = node->get_double("rate_hz", params.rate_hz);
  params.ramp_s = node->get_double("ramp_s", params.ramp_s);
  std::vector<double> lower, upper;
  for (const auto& a : model.actuators) {
    // Unlimited (continuous) joints get a wide symmetric room.
    lower.push_back(std::isfinite(a.lower_rad) ? a.lower_rad : -10.0);
    upper.push_back(std::isfinite(a.upper_rad) ? a.upper_rad : 10.0);
  }
  try {
    return excitation_trajectory(params, model.stand_pose_vector(), lower, upper);
  } catch (const std::invalid_argument& error) {
    node->fail(error.what());
  }
}

}  // namespace motoflex::detail
