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

NaoFootsteps::NaoFootsteps(const NaoWalkParams& p, double step_length_m) {
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
    step.swing_to_x = k + 1 == n ? support_x : support_x + (k == 0 ? 0.5 : 1.0) * step_length_m;
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
    return from + std::clamp(u, 0.0, 1.0) * (stand_zmp_end_m_ - from);
  }
  const NaoFootstep& step = steps_[k];
  const Eigen::Vector2d from = k == 0 ? stand_zmp_start_m_ : steps_[k - 1].zmp_end();
  const double in_step = t - step.start_s;
  if (in_step < double_support_s_) {
    return from + (in_step / double_support_s_) * (step.zmp_m - from);
  }
  const double u = (in_step - double_support_s_) / single_support_s_;
  return step.zmp_m + Eigen::Vector2d(std::clamp(u, 0.0, 1.0) * step.zmp_travel_m, 0.0);
}

void NaoFootsteps::feet(double t, double step_height_m, Eigen::Vector3d& left,
                        Eigen::Vector3d& right, NaoSupport& support) const {
  left = {0.0, half_spacing_m_, 0.0};
  right = {0.0, -half_spacing_m_, 0.0};
  support = NaoSupport::kDouble;
  const int k = step_at(t);
  // Positions after all steps that ended before t.
  const int done = k < 0 ? 0 : k;
  for (int i = 0; i < done && i < static_cast<int>(steps_.size()); ++i) {
    (steps_[i].support_left ? right : left).x() = steps_[i].swing_to_x;
  }
  if (k < 0 || k >= static_cast<int>(steps_.size())) return;
  const NaoFootstep& step = steps_[k];
  const double swing_t = t - step.start_s - double_support_s_;
  if (swing_t < 0.0) return;
  const double u = swing_t / single_support_s_;
  Eigen::Vector3d& swing = step.support_left ? right : left;
  swing.x() = step.swing_from_x + smooth(u) * (step.swing_to_x - step.swing_from_x);
  swing.z() = step_height_m * 0.5 * (1.0 - std::cos(2.0 * std::numbers::pi * u));
  support = step.support_left ? NaoSupport::kLeft : NaoSupport::kRight;
}

}  // namespace motoflex::detail
