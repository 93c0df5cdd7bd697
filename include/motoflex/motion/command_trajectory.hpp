#pragma once

#include <cstddef>
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

 private:
  std::vector<double> time_s_;
  std::vector<double> angles_rad_;
  std::size_t joints_ = 0;
};

}  // namespace motoflex
