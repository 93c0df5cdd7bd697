#include "nao_footsteps.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace motoflex::detail {
namespace {

// Quintic smoothstep: zero velocity and acceleration at both ends.
double smooth(double u) {
  u = std::clamp(u, 0.0, 1.0);
  return u * u * u * (10.0 + u * (-15.0 + 6.0 * u));
}

}  // namespace

double NaoFootsteps::transfer(double u) const {
  u = std::clamp(u, 0.0, 1.0);
  return (1.0 - transfer_smoothing_) * u + transfer_smoothing_ * smooth(u);
}

double NaoFootsteps::transfer_inverse(double share) const {
  share = std::clamp(share, 0.0, 1.0);
  if (transfer_smoothing_ == 0.0) return share;
  // transfer() rises monotonically from 0 to 1: bisection to well below a microsecond.
  double lo = 0.0, hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    (transfer(mid) < share ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

NaoFootsteps::NaoFootsteps(const NaoWalkParams& p, double step_length_m) {
  transfer_smoothing_ = p.zmp_transfer_smoothing;
  step_s_ = 0.5 * p.step_duration_s;
  double_support_s_ = p.double_support_ratio * step_s_;
  single_support_s_ = step_s_ - double_support_s_;
  half_spacing_m_ = 0.5 * p.foot_spacing_m;
  const int n =
      static_cast<int>(std::floor((p.duration_s - p.start_s - p.stop_s) / step_s_ + 1e-9));
  double x_left = 0.0, x_right = 0.0;
  bool support_left = !p.first_swing_left;
  for (int k = 0; k < n; ++k) {
    NaoFootstep step;
    step.support_left = support_left;
    step.start_s = p.start_s + k * step_s_;
    const double support_x = support_left ? x_left : x_right;
    double& swing_x = support_left ? x_right : x_left;
    step.swing_from_x = swing_x;
    // A half step starts the walk from the parallel stance. Walks with toe-off (long steps) also
    // end with one before the closing step, which then brings the rear foot only half a step
    // forward while the CoM comes to rest; flat-footed walks close from a full step behind.
    const bool half = k == 0 || (k + 2 == n && p.toe_off_rad > 0.0);
    step.swing_to_x = k + 1 == n ? support_x : support_x + (half ? 0.5 : 1.0) * step_length_m;
    swing_x = step.swing_to_x;
    const double inward = support_left ? -p.zmp_offset_y_m : p.zmp_offset_y_m;
    // Heel-to-toe: the ZMP rolls forward over the sole during single support, so the CoM need
    // not stop above one point (which would leave the feet far behind and ahead of it).
    step.zmp_travel_m = k == 0 || k + 1 == n ? 0.0 : std::min(p.zmp_travel_x_m, step_length_m);
    step.zmp_m = {support_x + p.zmp_offset_x_m - 0.5 * step.zmp_travel_m,
                  (support_left ? half_spacing_m_ : -half_spacing_m_) + inward};
    steps_.push_back(step);
    support_left = !support_left;
  }
  stand_zmp_start_m_ = {p.zmp_offset_x_m, 0.0};
  stand_zmp_end_m_ = {0.5 * (x_left + x_right) + p.zmp_offset_x_m, 0.0};
  end_transfer_s_ = std::max(double_support_s_, 0.1);
  steady_end_s_ = walk_end_s() - (p.toe_off_rad > 0.0 && n > 2 ? 2.0 : 1.0) * step_s_;
  if (p.toe_off_rad > 0.0 || p.heel_strike_rad > 0.0) plan_edge_contacts(p);
}

// Toe-off and heel strike happen in the double supports, where the reference ZMP moves from the
// rear foot (`from`) to the front one (`to`) along transfer(). The rear heel may rise only once the
// ZMP is past the rear toe edge, the front foot must be flat before the ZMP reaches its heel edge,
// either with kToeOffZmpMargin_m to spare; the angles shrink with the time left for them
// (kFullEdgeRoll_s). Short steps, whose ZMP never leaves the soles' overlap in x, stay flat.
void NaoFootsteps::plan_edge_contacts(const NaoWalkParams& p) {
  if (double_support_s_ <= 0.0) return;
  for (std::size_t k = 0; k < steps_.size(); ++k) {
    NaoFootstep& step = steps_[k];
    const double from_x = k == 0 ? stand_zmp_start_m_.x() : steps_[k - 1].zmp_end().x();
    const double to_x = step.zmp_m.x();
    if (to_x <= from_x) continue;
    // Time into the double support at which the ZMP passes x.
    const auto passes = [&](double x) {
      return transfer_inverse((x - from_x) / (to_x - from_x)) * double_support_s_;
    };
    const auto share = [](double window_s) { return std::min(1.0, window_s / kFullEdgeRoll_s); };
    // The closing step's rear foot is only half a step behind (walks with toe-off end with a
    // half step): it leaves flat.
    const bool closing = k + 1 == steps_.size();
    const double toe_s = passes(step.swing_from_x + kSoleFront_m + kToeOffZmpMargin_m);
    if (p.toe_off_rad > 0.0 && !closing && toe_s < double_support_s_) {
      step.toe_off_start_s = toe_s;
      step.lift_off_pitch_rad = p.toe_off_rad * share(double_support_s_ - toe_s);
    }
    // The front foot of this double support landed at the end of the previous step.
    if (k == 0 || !(p.heel_strike_rad > 0.0)) continue;
    const double support_x = steps_[k - 1].swing_to_x;
    const double heel_s = passes(support_x - kSoleBack_m - kToeOffZmpMargin_m);
    if (heel_s > 0.0) {
      step.heel_flat_s = heel_s;
      steps_[k - 1].touch_down_pitch_rad = -p.heel_strike_rad * share(heel_s);
    }
  }
}

int NaoFootsteps::step_at(double t) const {
  if (t < steps_.front().start_s) return -1;
  const int k = static_cast<int>(std::floor((t - steps_.front().start_s) / step_s_ + 1e-12));
  return std::min(k, static_cast<int>(steps_.size()));
}

Eigen::Vector2d NaoFootsteps::zmp_ref(double t) const {
  const int k = step_at(t);
  if (k < 0) return stand_zmp_start_m_;
  if (k >= static_cast<int>(steps_.size())) {
    const double u = (t - walk_end_s()) / end_transfer_s_;
    const Eigen::Vector2d from = steps_.back().zmp_end();
    return from + transfer(u) * (stand_zmp_end_m_ - from);
  }
  const NaoFootstep& step = steps_[k];
  const Eigen::Vector2d from = k == 0 ? stand_zmp_start_m_ : steps_[k - 1].zmp_end();
  const double in_step = t - step.start_s;
  if (in_step < double_support_s_) {
    return from + transfer(in_step / double_support_s_) * (step.zmp_m - from);
  }
  const double u = (in_step - double_support_s_) / single_support_s_;
  return step.zmp_m + Eigen::Vector2d(std::clamp(u, 0.0, 1.0) * step.zmp_travel_m, 0.0);
}

void NaoFootsteps::feet(double t, double step_height_m, NaoEdgeFoot& left, NaoEdgeFoot& right,
                        NaoSupport& support) const {
  left = {};
  right = {};
  left.edge_m = {0.0, half_spacing_m_, 0.0};
  right.edge_m = {0.0, -half_spacing_m_, 0.0};
  support = NaoSupport::kDouble;
  const int k = step_at(t);
  // Positions after all steps that ended before t.
  const int done = k < 0 ? 0 : k;
  for (int i = 0; i < done && i < static_cast<int>(steps_.size()); ++i) {
    (steps_[i].support_left ? right : left).edge_m.x() = steps_[i].swing_to_x;
  }
  if (k < 0 || k >= static_cast<int>(steps_.size())) return;
  const NaoFootstep& step = steps_[k];
  NaoEdgeFoot& swing = step.support_left ? right : left;
  const double in_step = t - step.start_s;
  if (in_step < double_support_s_) {
    if (step.lift_off_pitch_rad > 0.0 && in_step > step.toe_off_start_s) {
      // Heel rising about the toe edge, which stays where it is.
      swing.edge_m.x() = step.swing_from_x + kSoleFront_m;
      swing.edge_x_m = kSoleFront_m;
      swing.pitch_rad =
          step.lift_off_pitch_rad *
          smooth((in_step - step.toe_off_start_s) / (double_support_s_ - step.toe_off_start_s));
    }
    if (k > 0 && steps_[k - 1].touch_down_pitch_rad < 0.0 && in_step < step.heel_flat_s) {
      // Landed on the heel edge, toes up: rolling down flat about it.
      NaoEdgeFoot& front = step.support_left ? left : right;
      front.edge_m.x() -= kSoleBack_m;
      front.edge_x_m = -kSoleBack_m;
      front.pitch_rad =
          steps_[k - 1].touch_down_pitch_rad * (1.0 - smooth(in_step / step.heel_flat_s));
    }
    return;
  }
  const double u = (in_step - double_support_s_) / single_support_s_;
  swing.edge_m.x() = step.swing_from_x + smooth(u) * (step.swing_to_x - step.swing_from_x);
  swing.edge_m.z() = step_height_m * 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * u));
  // From toe-off to heel strike the foot turns from toes down to toes up along with its forward
  // motion; the lowest edge (the toe edge while the toes point down, the heel edge after) stays
  // on the path, so the foot never dips below the ground.
  if (step.lift_off_pitch_rad != 0.0 || step.touch_down_pitch_rad != 0.0) {
    // The toes-up part comes late (squared): a foot still behind the body cannot dorsiflex.
    const double w = smooth(u);
    const double pitch = step.lift_off_pitch_rad * (1.0 - w) + step.touch_down_pitch_rad * w * w;
    if (pitch != 0.0) {
      swing.edge_x_m = pitch > 0.0 ? kSoleFront_m : -kSoleBack_m;
      swing.edge_m.x() += swing.edge_x_m;
      swing.pitch_rad = pitch;
    }
  }
  support = step.support_left ? NaoSupport::kLeft : NaoSupport::kRight;
}

}  // namespace motoflex::detail
