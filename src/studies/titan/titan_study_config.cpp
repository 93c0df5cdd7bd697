#include "motoflex/studies/titan/titan_study_config.hpp"

#include <filesystem>
#include <memory>
#include <stdexcept>
#include <utility>

#include "motoflex/core/error.hpp"
#include "motoflex/io/yaml_reader.hpp"
#include "motoflex/motion/titan_leg_kinematics.hpp"
#include "motoflex/scenario/scenario.hpp"
#include "motoflex/sim/robot_parameter_check.hpp"

namespace motoflex {
namespace {

TitanPosture read_posture(const YamlValue& value) {
  const auto posture = parse_titan_posture(value.as_string());
  if (!posture) value.fail("expected A, B, C or D");
  return *posture;
}

TitanPosture posture_or(const YamlValue& spec, TitanPosture fallback) {
  const auto field = spec.find("posture");
  return field ? read_posture(*field) : fallback;
}

double positive(const YamlValue& spec, const char* key, double fallback) {
  const double value = spec.get_double(key, fallback);
  if (!(value > 0.0)) spec.at(key).fail("must be positive");
  return value;
}

double non_negative(const YamlValue& spec, const char* key, double fallback) {
  const double value = spec.get_double(key, fallback);
  if (!(value >= 0.0)) spec.at(key).fail("must be >= 0");
  return value;
}

TitanLeg read_leg(const YamlValue& value) {
  const std::string text = value.as_string();
  for (const TitanLeg leg : kTitanLegs) {
    if (text == to_string(leg)) return leg;
  }
  value.fail("expected FL, FR, HL or HR");
}

std::shared_ptr<const RobotModel> read_robot(const YamlValue& root, double& clearance_m,
                                             bool& clearance_given) {
  const YamlValue robot_field = root.at("robot");
  const std::string robot_dir = robot_field.resolve_path(robot_field.as_string());
  if (!std::filesystem::exists(std::filesystem::path(robot_dir) / "robot.yaml")) {
    robot_field.fail("no robot.yaml in '" + robot_dir + "'");
  }
  auto model = std::make_shared<RobotModel>(load_robot(robot_dir, StructureOptions{}));
  if (clearance_given) model->initial_clearance_m = clearance_m;
  try {
    const TitanKinematics kinematics(*model);
  } catch (const std::invalid_argument& error) {
    robot_field.fail(std::string("not a TITAN-VIII-like robot: ") + error.what());
  }
  return model;
}

void read_physics(const YamlValue& root, RolloutOptions& rollout, double& clearance_m,
                  bool& clearance_given) {
  const auto physics = root.find("physics");
  if (!physics) return;
  physics->require_keys_within({"dt_s", "solver", "initial_clearance_m"});
  read_step_settings(*physics, rollout);
  if (const auto clearance = physics->find("initial_clearance_m")) {
    clearance_m = clearance->as_double();
    if (!(clearance_m >= 0.0 && clearance_m <= 0.1)) clearance->fail("must be in [0, 0.1] m");
    clearance_given = true;
  }
}

void set_parameter(const YamlValue& value, const std::string& name, ParameterSet& parameters) {
  if (!parameters.registry().contains(name)) {
    const std::string hint = parameters.registry().closest_name(name);
    value.fail("robot has no parameter '" + name + "'" +
               (hint.empty() ? "" : " (did you mean '" + hint + "'?)"));
  }
  parameters.set(name, value.as_double());
}

void read_contact_and_parameters(const YamlValue& root, ParameterSet& parameters) {
  if (const auto contact = root.find("contact")) {
    contact->require_keys_within({"mu", "slip", "soft_erp", "soft_cfm"});
    for (const auto& [key, value] : contact->entries()) {
      if (!(value.as_double() > 0.0)) value.fail("must be positive");
      if ((key == "soft_erp") && !(value.as_double() <= 1.0)) value.fail("must be in (0, 1]");
      set_parameter(value, "contact." + key, parameters);
    }
  }
  if (const auto overrides = root.find("parameters")) {
    for (const auto& [name, value] : overrides->entries()) set_parameter(value, name, parameters);
  }
}

void read_static(const YamlValue& spec, TitanStaticOptions& options) {
  spec.require_keys_within({"posture", "duration_s", "cut_after_touchdown_s", "converge_fraction",
                            "converge_reference_nm", "final_window_s"});
  options.posture = posture_or(spec, options.posture);
  options.duration_s = positive(spec, "duration_s", options.duration_s);
  options.cut_after_touchdown_s =
      non_negative(spec, "cut_after_touchdown_s", options.cut_after_touchdown_s);
  options.converge_fraction = positive(spec, "converge_fraction", options.converge_fraction);
  if (options.converge_fraction >= 1.0) spec.at("converge_fraction").fail("must be below 1");
  options.converge_reference_nm =
      non_negative(spec, "converge_reference_nm", options.converge_reference_nm);
  options.final_window_s = positive(spec, "final_window_s", options.final_window_s);
  if (options.final_window_s + options.cut_after_touchdown_s + 0.1 >= options.duration_s) {
    spec.fail("duration_s must exceed final_window_s + cut_after_touchdown_s + 0.1 s (landing)");
  }
}

void read_updown(const YamlValue& spec, TitanUpDownStudyOptions& options) {
  spec.require_keys_within({"posture", "amplitude_m", "period_s", "periods", "settle_s"});
  TitanUpDownOptions& motion = options.motion;
  motion.posture = posture_or(spec, motion.posture);
  motion.amplitude_m = positive(spec, "amplitude_m", motion.amplitude_m);
  motion.period_s = positive(spec, "period_s", motion.period_s);
  motion.periods = spec.get_int("periods", motion.periods);
  if (motion.periods < 2) spec.at("periods").fail("must be >= 2 (the rise is taken in the 2nd)");
  if (const std::string reason = motion.invalid_reason(); !reason.empty()) spec.fail(reason);
  options.settle_s = non_negative(spec, "settle_s", options.settle_s);
}

void read_crawl(const YamlValue& spec, TitanCrawlStudyOptions& options,
                std::vector<TitanPosture>& postures) {
  spec.require_keys_within({"postures", "periods", "settle_s", "plot_leg", "exchange_window_s"});
  if (const auto list = spec.find("postures")) {
    postures.clear();
    for (const YamlValue& item : list->items()) {
      const TitanPosture posture = read_posture(item);
      for (const TitanPosture seen : postures) {
        if (seen == posture) item.fail("posture listed twice");
      }
      postures.push_back(posture);
    }
    if (postures.empty()) list->fail("list at least one posture");
  }
  options.periods = spec.get_int("periods", options.periods);
  if (options.periods < 1) spec.at("periods").fail("must be >= 1");
  options.settle_s = non_negative(spec, "settle_s", options.settle_s);
  if (const auto leg = spec.find("plot_leg")) options.plot_leg = read_leg(*leg);
  if (const auto window = spec.find("exchange_window_s")) {
    const std::vector<double> w = window->as_double_list();
    const double period_s = TitanCrawlOptions{}.period_s;
    if (w.size() != 2 || !(w[0] >= 0.0 && w[0] < w[1] && w[1] <= period_s)) {
      window->fail("expected [from, to] with 0 <= from < to <= the gait period (4.8 s)");
    }
    options.exchange_from_s = w[0];
    options.exchange_to_s = w[1];
  }
}

}  // namespace

TitanStudyConfig load_titan_study_config(const std::string& path) {
  const YamlValue root = YamlValue::load_file(path);
  root.require_keys_within({"name", "robot", "servo", "physics", "contact", "parameters",
                            "commands", "static", "updown", "crawl", "timing"});
  RolloutOptions rollout;
  rollout.servo = "velocity";
  double clearance_m = 0.0;
  bool clearance_given = false;
  read_physics(root, rollout, clearance_m, clearance_given);
  std::shared_ptr<const RobotModel> model = read_robot(root, clearance_m, clearance_given);
  if (const auto servo = root.find("servo")) {
    const std::string name = servo->as_string();
    if (name != "velocity" && name != "ideal") {
      servo->fail(
          "expected velocity (eq. 3, the paper's) or ideal: joint feedback sees only servos "
          "that act through ODE joint motors");
    }
    rollout.servo = name;
  }
  const YamlValue servo_field = root.find("servo") ? root.at("servo") : root.at("robot");
  check_servo_parameters(*model, rollout.servo, path, servo_field.line(), servo_field.field());

  TitanStudySetup setup(model);
  setup.rollout = rollout;
  TitanStudyConfig config{path, root.get_string("name", "titan_paper"),
                          TitanPaperStudyPlan(std::move(setup))};
  TitanPaperStudyPlan& plan = config.plan;
  read_contact_and_parameters(root, plan.setup.parameters);
  plan.setup.servo_lead = rollout.servo == "velocity";
  if (const auto commands = root.find("commands")) {
    commands->require_keys_within({"rate_hz", "servo_lead"});
    plan.setup.command_rate_hz = positive(*commands, "rate_hz", plan.setup.command_rate_hz);
    plan.setup.servo_lead = commands->get_bool("servo_lead", plan.setup.servo_lead);
    if (plan.setup.servo_lead && rollout.servo != "velocity") {
      commands->at("servo_lead").fail("needs the velocity servo");
    }
  }
  if (const auto spec = root.find("static")) read_static(*spec, plan.stand);
  if (const auto spec = root.find("updown")) read_updown(*spec, plan.updown);
  if (const auto spec = root.find("crawl")) read_crawl(*spec, plan.crawl, plan.crawl_postures);
  if (const auto timing = root.find("timing")) {
    timing->require_keys_within({"crawl_s", "posture", "repeats"});
    plan.timing_repeats = timing->get_int("repeats", plan.timing_repeats);
    if (plan.timing_repeats < 1) timing->at("repeats").fail("must be >= 1");
    plan.timing_crawl_s = non_negative(*timing, "crawl_s", plan.timing_crawl_s);
    plan.timing_posture = posture_or(*timing, plan.timing_posture);
  }
  return config;
}

}  // namespace motoflex
