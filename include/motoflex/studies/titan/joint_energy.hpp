#pragma once

#include <cstddef>
#include <vector>

namespace motoflex {

// Mechanical work bookkeeping of a set of joints (seed 000 §V-B, §VI). Each physics step adds
// the joint power P = τ·ω of every channel times the step; the meter keeps ∫P dt (net work) and
// ∫|P| dt per channel and the time covered.
class JointEnergyMeter {
 public:
  explicit JointEnergyMeter(std::size_t channels = 0);

  // Adds P·dt and |P|·dt to `channel`. Call once per channel per step, then `advance(dt_s)`.
  void add(std::size_t channel, double power_w, double dt_s);
  void advance(double dt_s) { duration_s_ += dt_s; }

  std::size_t channels() const { return work_j_.size(); }
  double duration_s() const { return duration_s_; }
  double work_j(std::size_t channel) const { return work_j_.at(channel); }
  double absolute_work_j(std::size_t channel) const { return absolute_work_j_.at(channel); }
  double total_work_j() const;

  // Time average of |P| of one channel [W] (0 before any time has passed).
  double averaged_absolute_power_w(std::size_t channel) const;
  // Seed 000 eq. 8: |P̄| = 1/(nT) ∫₀^{nT} Σ_i Σ_j |P_ij| dt over all channels [W].
  double averaged_absolute_power_w() const;

 private:
  std::vector<double> work_j_;
  std::vector<double> absolute_work_j_;
  double duration_s_ = 0.0;
};

}  // namespace motoflex
