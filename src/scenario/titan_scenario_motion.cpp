#include "titan_scenario_motion.hpp"

#include <memory>
#include <stdexcept>

#include "motoflex/motion/titan_gait.hpp"

namespace motoflex::detail {
namespace {

TitanPosture read_posture(const YamlValue& spec) {
  const auto field = spec.find("posture");
  if (!field) return TitanPosture::kA;
  const auto posture = parse_titan_posture(field->as_string());
  if (!posture) field->fail("expected A, B, C or D");
  return *posture;
}

double read_rate_hz(const YamlValue& spec) {
  const double rate_hz = spec.get_double("rate_hz", 100.0);
  if (!(rate_hz > 0.0)) spec.at("rate_hz").fail("must be positive");
  return rate_hz;
}

TitanCommandOptions read_command_options(const YamlValue& spec, const RobotModel& model,
                                         const ParameterSet& parameters, const std::string& servo) {
  TitanCommandOptions options;
  options.rate_hz = read_rate_hz(spec);
  const bool velocity = servo == "velocity";
  const bool lead = spec.get_bool("servo_lead", velocity);
  if (lead && !velocity) spec.at("servo_lead").fail("needs the velocity servo");
  if (lead) options.lead_gain_per_s = velocity_servo_gains_per_s(model, parameters);
  return options;
}

}  // namespace

std::optional<TitanScenarioMotion> titan_motion_from_yaml(const YamlValue& motion,
                                                          const RobotModel& model,
                                                          const ParameterSet& parameters,
                                                          const std::string& servo) {
  std::optional<YamlValue> spec;
  for (const char* key : {"titan_crawl", "titan_updown", "titan_stand"}) {
    if (const auto found = motion.find(key)) spec = found;
  }
  if (!spec) return std::nullopt;

  std::unique_ptr<TitanFootPlan> plan;
  TitanCommandOptions options;
  if (motion.find("titan_crawl")) {
    spec->require_keys_within({"posture", "periods", "rate_hz", "servo_lead"});
    TitanCrawlOptions crawl;
    crawl.posture = read_posture(*spec);
    crawl.periods = spec->get_int("periods", 1);
    if (crawl.periods < 1) spec->at("periods").fail("must be >= 1");
    plan = std::make_unique<TitanCrawl>(crawl);
    options = read_command_options(*spec, model, parameters, servo);
  } else if (motion.find("titan_updown")) {
    spec->require_keys_within(
        {"posture", "amplitude_m", "period_s", "periods", "rate_hz", "servo_lead"});
    TitanUpDownOptions updown;
    updown.posture = read_posture(*spec);
    updown.amplitude_m = spec->get_double("amplitude_m", updown.amplitude_m);
    updown.period_s = spec->get_double("period_s", updown.period_s);
    updown.periods = spec->get_int("periods", updown.periods);
    if (const std::string reason = updown.invalid_reason(); !reason.empty()) spec->fail(reason);
    plan = std::make_unique<TitanUpDown>(updown);
    options = read_command_options(*spec, model, parameters, servo);
  } else {
    spec->require_keys_within({"duration_s", "posture", "rate_hz"});
    const double duration_s = spec->at("duration_s").as_double();
    if (!(duration_s > 0.0)) spec->at("duration_s").fail("must be positive");
    plan = std::make_unique<TitanStand>(read_posture(*spec), duration_s);
    options.rate_hz = read_rate_hz(*spec);
  }

  try {
    const TitanKinematics kinematics(model);
    return TitanScenarioMotion{titan_command_trajectory(kinematics, *plan, options),
                               options.rate_hz, plan->description()};
  } catch (const std::invalid_argument& error) {  // not a TITAN-VIII-like robot
    spec->fail(error.what());
  } catch (const TitanUnreachable& error) {
    spec->fail(error.what());
  }
}

}  // namespace motoflex::detail
