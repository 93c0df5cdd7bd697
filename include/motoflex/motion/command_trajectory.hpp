#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace motoflex {

// Commanded joint angles at log rate (e.g. 50 or 100 Hz), for the actuated joints in model
// order. The physics reads them at 1 kHz by linear interpolation (seed 001 code: target
// angles at 50 Hz, linearly interpolated).
class CommandTrajectory {
 public:
  CommandTrajectory() = default;
  // Throws std::invalid_argument unless times strictly increase, there are >= 2 frames and
  // angles has frames × joints entries (frame-major).
  CommandTrajectory(std::vector<double> time_s, std::vector<double> angles_rad, std::size_t joints);

  std::size_t frames() const { return time_s_.size(); }
  std::size_t joints() const { return joints_; }
  double time_s(std::size_t frame) const { return time_s_[frame]; }
  const std::vector<double>& times_s() const { return time_s_; }
  double angle_rad(std::size_t frame, std::size_t joint) const {
    return angles_rad_[frame * joints_ + joint];
  }
  const std::vector<double>& angles_rad() const { return angles_rad_; }
  double start_s() const { return time_s_.front(); }
  double duration_s() const { return time_s_.back() - time_s_.front(); }

  // Interpolates every joint at absolute time t_s (clamped to the first/last frame) into
  // out[0..joints). `hint` is the frame to start searching from and is updated, so sweeping
  // forward in time costs O(1) per call.
  void sample(double t_s, double* out, std::size_t& hint) const;

  // The supply voltage the robot logged with these commands (V, one per frame), smoothed by a
  // centred moving average over kSupplySmoothing_s: the servo's register reads in 0.1 V steps,
  // each read a few ms apart, while the voltage behind it moves with the motor current. Throws
  // std::invalid_argument unless there is one finite positive value per frame.
  void set_supply_v(const std::vector<double>& logged_v) {
    set_smoothed_supply_v(smoothed_supply_v(time_s_, logged_v));
  }
  // Values already smoothed (e.g. over a whole log of which this is the first part).
  void set_smoothed_supply_v(std::vector<double> supply_v);
  // The centred moving average of logged_v (one per time) over kSupplySmoothing_s.
  static std::vector<double> smoothed_supply_v(const std::vector<double>& time_s,
                                               const std::vector<double>& logged_v);
  bool has_supply() const { return !supply_v_.empty(); }
  const std::vector<double>& supply_v() const { return supply_v_; }  // smoothed, per frame
  // The smoothed supply at absolute time t_s (linear between frames, clamped at the ends); NaN
  // without a logged supply. `hint` as for sample().
  double supply_v_at(double t_s, std::size_t& hint) const;
  static constexpr double kSupplySmoothing_s = 0.1;

 private:
  std::vector<double> time_s_;
  std::vector<double> angles_rad_;
  std::vector<double> supply_v_;  // empty: no logged supply
  std::size_t joints_ = 0;
};

}  // namespace motoflex
