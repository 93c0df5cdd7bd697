#include "motoflex/motion/titan_gait.hpp"

#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace motoflex {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Position of each leg in the swing sequence FL → HR → FR → HL (classic crawl).
int swing_slot(TitanLeg leg) {
  switch (leg) {
    case TitanLeg::kFL:
      return 0;
    case TitanLeg::kHR:
      return 1;
    case TitanLeg::kFR:
      return 2;
    case TitanLeg::kHL:
      return 3;
  }
  return 0;
}

// Time since the leg's lift-off, as a fraction of a quarter period, in [0, 4). Every leg is
// measured from the same quarter-period count of t, so at a switch instant exactly one leg is
// in swing whatever the rounding of t.
double quarters_since_lift_off(TitanLeg leg, double t_s, double period_s) {
  const double quarters = 4.0 * t_s / period_s;
  const double whole = std::floor(quarters);
  const long long slot = static_cast<long long>(whole) - swing_slot(leg);
  return static_cast<double>(((slot % 4) + 4) % 4) + (quarters - whole);
}

std::string format_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

}  // namespace

std::optional<TitanPosture> parse_titan_posture(std::string_view text) {
  if (text == "A") return TitanPosture::kA;
  if (text == "B") return TitanPosture::kB;
  if (text == "C") return TitanPosture::kC;
  if (text == "D") return TitanPosture::kD;
  return std::nullopt;
}

const char* to_string(TitanPosture posture) {
  switch (posture) {
    case TitanPosture::kA:
      return "A";
    case TitanPosture::kB:
      return "B";
    case TitanPosture::kC:
      return "C";
    case TitanPosture::kD:
      return "D";
  }
  return "?";
}

TitanPostureSpec titan_posture(TitanPosture posture) {
  // A: scenarios/robots/titan8/README.md standard posture. B–D: 0.06 m inward / outward /
  // forward of A (why: titan_gait.hpp).
  switch (posture) {
    case TitanPosture::kA:
      return {0.25, 0.4028};
    case TitanPosture::kB:
      return {0.25, 0.3428};
    case TitanPosture::kC:
      return {0.25, 0.4628};
    case TitanPosture::kD:
      return {0.31, 0.4028};
  }
  return {0.25, 0.4028};
}

Eigen::Vector3d titan_stroke_centre_m(TitanPosture posture, TitanLeg leg, double sole_z_m) {
  const TitanPostureSpec p = titan_posture(posture);
  const bool fore = leg == TitanLeg::kFL || leg == TitanLeg::kFR;
  const bool left = leg == TitanLeg::kFL || leg == TitanLeg::kHL;
  return {fore ? p.foot_x_m : -p.foot_x_m, left ? p.foot_y_m : -p.foot_y_m, sole_z_m};
}

CommandTrajectory titan_command_trajectory(const TitanKinematics& kinematics,
                                           const TitanFootPlan& plan,
                                           const TitanCommandOptions& options) {
  const double rate_hz = options.rate_hz;
  if (!(rate_hz > 0.0)) throw std::invalid_argument("TITAN trajectory rate must be positive");
  const std::size_t n = kinematics.actuator_count();
  const std::vector<double>& gains = options.lead_gain_per_s;
  if (!gains.empty() && gains.size() != n) {
    throw std::invalid_argument("TITAN trajectory: one lead gain per actuator needed");
  }
  for (const double k : gains) {
    if (!(k > 0.0)) throw std::invalid_argument("TITAN trajectory: lead gains must be positive");
  }
  const auto pose_at = [&](double t) {
    std::array<Eigen::Vector3d, 4> soles;
    for (const TitanLeg leg : kTitanLegs) {
      soles[static_cast<std::size_t>(leg)] = plan.sole_position_m(leg, t);
    }
    return kinematics.pose_rad(soles);
  };
  const double duration = plan.duration_s();
  // Frame k at k / rate (exact multiples, so phase boundaries land on frames); the last frame
  // is the end of the plan.
  const auto regular = static_cast<std::size_t>(std::ceil(duration * rate_hz - 1e-9));
  std::vector<double> times;
  times.reserve(regular + 1);
  for (std::size_t k = 0; k < regular; ++k) times.push_back(static_cast<double>(k) / rate_hz);
  times.push_back(duration);
  std::vector<double> angles;
  angles.reserve(times.size() * n);
  constexpr double kRateStep_s = 1e-4;  // central difference of the plan for the lead
  for (const double t : times) {
    std::vector<double> pose = pose_at(t);
    if (!gains.empty()) {
      const std::vector<double> before = pose_at(t - kRateStep_s);
      const std::vector<double> after = pose_at(t + kRateStep_s);
      for (std::size_t j = 0; j < n; ++j) {
        pose[j] += (after[j] - before[j]) / (2.0 * kRateStep_s) / gains[j];
      }
    }
    angles.insert(angles.end(), pose.begin(), pose.end());
  }
  return CommandTrajectory(std::move(times), std::move(angles), n);
}

std::vector<double> velocity_servo_gains_per_s(const RobotModel& model,
                                               const ParameterSet& parameters) {
  std::vector<double> gains;
  for (const ActuatorSpec& actuator : model.actuators) {
    gains.push_back(parameters.get("joint." + actuator.name + ".gain_per_s"));
  }
  return gains;
}

// ---- crawl ----

std::string TitanCrawlOptions::invalid_reason() const {
  if (!(period_s > 0.0)) return "period_s must be positive";
  if (!(duty_factor >= 0.75 && duty_factor < 1.0)) {
    return "duty_factor must be in [0.75, 1) so that only one leg swings at a time";
  }
  if (!(stroke_m > 0.0)) return "stroke_m must be positive";
  if (!(swing_height_m >= 0.0)) return "swing_height_m must be >= 0";
  if (!(sole_z_m < 0.0)) return "sole_z_m must be negative (the soles are below the hips)";
  if (periods < 1) return "periods must be >= 1";
  return {};
}

TitanCrawl::TitanCrawl(const TitanCrawlOptions& options) : options_(options) {
  if (const std::string reason = options.invalid_reason(); !reason.empty()) {
    throw std::invalid_argument("TITAN crawl: " + reason);
  }
}

double TitanCrawl::swing_start_s(TitanLeg leg) const {
  return swing_slot(leg) * options_.period_s / 4.0;
}

Eigen::Vector3d TitanCrawl::stroke_centre_m(TitanLeg leg) const {
  return titan_stroke_centre_m(options_.posture, leg, options_.sole_z_m);
}

TitanLegPhase TitanCrawl::phase(TitanLeg leg, double t_s) const {
  const double swing_quarters = 4.0 * (1.0 - options_.duty_factor);
  return quarters_since_lift_off(leg, t_s, options_.period_s) < swing_quarters
             ? TitanLegPhase::kSwing
             : TitanLegPhase::kStance;
}

Eigen::Vector3d TitanCrawl::sole_position_m(TitanLeg leg, double t_s) const {
  const double stroke = options_.stroke_m;
  Eigen::Vector3d p = stroke_centre_m(leg);
  const double swing_quarters = 4.0 * (1.0 - options_.duty_factor);
  const double c = quarters_since_lift_off(leg, t_s, options_.period_s);
  if (c < swing_quarters) {
    // Cycloid from the rear to the front end of the stroke: zero velocity at both ends.
    const double s = c / swing_quarters;
    p.x() += stroke * (s - std::sin(kTwoPi * s) / kTwoPi - 0.5);
    p.z() += 0.5 * options_.swing_height_m * (1.0 - std::cos(kTwoPi * s));
  } else {
    // Stance: straight backward relative to the body at constant speed and height.
    const double s = (c - swing_quarters) / (4.0 - swing_quarters);
    p.x() += stroke * (0.5 - s);
  }
  return p;
}

std::string TitanCrawl::description() const {
  return std::string("TITAN-VIII crawl, posture ") + to_string(options_.posture) + ", " +
         std::to_string(options_.periods) + " x " + format_number(options_.period_s) + " s, duty " +
         format_number(options_.duty_factor);
}

// ---- up-and-down ----

std::string TitanUpDownOptions::invalid_reason() const {
  if (!(period_s > 0.0)) return "period_s must be positive";
  if (!(amplitude_m >= 0.0)) return "amplitude_m must be >= 0";
  if (!(mean_sole_z_m < 0.0)) return "mean_sole_z_m must be negative";
  if (!(amplitude_m < -mean_sole_z_m)) return "amplitude_m must be smaller than the mean height";
  if (periods < 1) return "periods must be >= 1";
  return {};
}

TitanUpDown::TitanUpDown(const TitanUpDownOptions& options) : options_(options) {
  if (const std::string reason = options.invalid_reason(); !reason.empty()) {
    throw std::invalid_argument("TITAN up-and-down: " + reason);
  }
}

double TitanUpDown::body_height_m(double t_s) const {
  return -options_.mean_sole_z_m +
         options_.amplitude_m * std::sin(kTwoPi * t_s / options_.period_s);
}

Eigen::Vector3d TitanUpDown::sole_position_m(TitanLeg leg, double t_s) const {
  // The feet stay put on the ground, so in the body frame they move opposite to the body.
  return titan_stroke_centre_m(options_.posture, leg, -body_height_m(t_s));
}

std::string TitanUpDown::description() const {
  return std::string("TITAN-VIII up-and-down, posture ") + to_string(options_.posture) + ", +-" +
         format_number(options_.amplitude_m) + " m, " + std::to_string(options_.periods) + " x " +
         format_number(options_.period_s) + " s";
}

// ---- standing ----

TitanStand::TitanStand(TitanPosture posture, double duration_s, double sole_z_m)
    : posture_(posture), duration_s_(duration_s), sole_z_m_(sole_z_m) {
  if (!(duration_s > 0.0)) throw std::invalid_argument("TITAN stand: duration_s must be positive");
  if (!(sole_z_m < 0.0)) throw std::invalid_argument("TITAN stand: sole_z_m must be negative");
}

Eigen::Vector3d TitanStand::sole_position_m(TitanLeg leg, double) const {
  return titan_stroke_centre_m(posture_, leg, sole_z_m_);
}

std::string TitanStand::description() const {
  return std::string("TITAN-VIII standing, posture ") + to_string(posture_);
}

}  // namespace motoflex
