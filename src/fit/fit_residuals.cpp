#include "fit_residuals.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>

#include "motoflex/sim/ode_runtime.hpp"

namespace motoflex::detail {

FitResiduals::FitResiduals(const FitConfig& config, int threads)
    : config_(config), threads_(std::max(threads, 1)) {
  const FitnessFunction& f = *config.train;
  for (const FitCase& c : f.cases()) {
    const std::size_t first = first_scored_frame(c, f.options().settle_s);
    const double frames = static_cast<double>(c.commands.frames() - first);
    first_frame_.push_back(first);
    scale_.push_back(1.0 / std::sqrt(std::pow(frames, f.options().m)));
    size_ += (c.commands.frames() - first) * f.channels();
  }
}

std::size_t FitResiduals::dimension() const {
  return config_.space->dimension();
}

bool FitResiduals::evaluate(const std::vector<double>& x, double* out) const {
  const FitnessFunction& f = *config_.train;
  std::vector<RolloutResult> rollouts;
  FitnessBreakdown scores;
  try {
    scores = f.evaluate(config_.space->apply(x), std::numeric_limits<double>::infinity(), &rollouts,
                        threads_);
  } catch (const std::bad_alloc&) {
    throw;
  } catch (const std::exception&) {
    return false;  // a candidate the model rejects
  }
  const std::size_t channels = f.channels();
  std::vector<double> sim(channels), real(channels);
  std::size_t k = 0;
  for (std::size_t c = 0; c < f.cases().size(); ++c) {
    const CaseScore& score = scores.cases[c];
    if (score.frames != score.frames_requested || !std::isfinite(score.fitness)) return false;
    for (std::size_t t = first_frame_[c]; t < f.cases()[c].commands.frames(); ++t) {
      f.simulated_channels(rollouts[c], t, sim.data());
      f.measured_channels(c, t, real.data());
      for (std::size_t j = 0; j < channels; ++j) {
        out[k++] = scale_[c] * f.channel_residual(j, real[j] - sim[j]);
      }
    }
  }
  return true;
}

std::uint64_t FitResiduals::evaluate_points(const std::vector<std::vector<double>>& points,
                                            std::vector<std::vector<double>>& r,
                                            std::vector<char>& ok) const {
  r.assign(points.size(), {});
  ok.assign(points.size(), 0);
  ensure_ode_ready();  // the process-wide part, before the workers start
  // Each point is independent (its logs simulated serially), so the order of the workers does
  // not change any number.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_)
  for (long q = 0; q < static_cast<long>(points.size()); ++q) {
    const auto s = static_cast<std::size_t>(q);
    ensure_ode_ready();  // this worker's own ODE data
    FitResiduals serial(*this);
    serial.threads_ = 1;
    r[s].resize(size_);
    ok[s] = serial.evaluate(points[s], r[s].data()) ? 1 : 0;
  }
  return points.size();
}

std::uint64_t FitResiduals::jacobian(const std::vector<double>& x, const std::vector<double>& r0,
                                     double step, std::vector<double>& out,
                                     FiniteDifferences scheme) const {
  const std::size_t p = dimension(), n = size_;
  const std::vector<double> lower = config_.space->lower(), upper = config_.space->upper();
  std::vector<double> h(p);
  for (std::size_t i = 0; i < p; ++i) h[i] = step * (upper[i] - lower[i]);
  // The points of one pass: coordinate i moved by sign·h_i where `sign` is ±1 and the point
  // stays within the bounds; `column[k]` is the coordinate of point k.
  struct Pass {
    std::vector<std::vector<double>> points;
    std::vector<std::size_t> column;
    std::vector<double> offset;
    std::vector<std::vector<double>> r;
    std::vector<char> ok;
  };
  const auto add = [&](Pass& pass, std::size_t i, double sign) {
    const double at = x[i] + sign * h[i];
    if (at > upper[i] || at < lower[i]) return false;
    pass.points.push_back(x);
    pass.points.back()[i] = at;
    pass.column.push_back(i);
    pass.offset.push_back(sign * h[i]);
    return true;
  };
  std::uint64_t rollouts = 0;
  out.assign(n * p, 0.0);
  if (scheme == FiniteDifferences::kCentral) {
    // Two points per coordinate (x + h, x − h); a side outside the bounds is skipped.
    Pass pass;
    std::vector<std::ptrdiff_t> plus(p, -1), minus(p, -1);
    for (std::size_t i = 0; i < p; ++i) {
      if (add(pass, i, 1.0)) plus[i] = static_cast<std::ptrdiff_t>(pass.points.size() - 1);
      if (add(pass, i, -1.0)) minus[i] = static_cast<std::ptrdiff_t>(pass.points.size() - 1);
    }
    rollouts += evaluate_points(pass.points, pass.r, pass.ok);
    for (std::size_t i = 0; i < p; ++i) {
      const bool up = plus[i] >= 0 && pass.ok[static_cast<std::size_t>(plus[i])] != 0;
      const bool down = minus[i] >= 0 && pass.ok[static_cast<std::size_t>(minus[i])] != 0;
      if (!up && !down) continue;
      const double* a = up ? pass.r[static_cast<std::size_t>(plus[i])].data() : r0.data();
      const double* b = down ? pass.r[static_cast<std::size_t>(minus[i])].data() : r0.data();
      const double width = (up ? h[i] : 0.0) + (down ? h[i] : 0.0);
      for (std::size_t k = 0; k < n; ++k) out[k * p + i] = (a[k] - b[k]) / width;
    }
    return rollouts;
  }
  // Forward: x + h_i, else x − h_i; a failed side is retried on the other in a second pass.
  Pass first;
  for (std::size_t i = 0; i < p; ++i) {
    if (!add(first, i, 1.0)) add(first, i, -1.0);
  }
  rollouts += evaluate_points(first.points, first.r, first.ok);
  Pass retry;
  for (std::size_t k = 0; k < first.points.size(); ++k) {
    if (first.ok[k] == 0) add(retry, first.column[k], first.offset[k] > 0.0 ? -1.0 : 1.0);
  }
  if (!retry.points.empty()) rollouts += evaluate_points(retry.points, retry.r, retry.ok);
  for (const Pass* pass : {&first, &retry}) {
    for (std::size_t k = 0; k < pass->points.size(); ++k) {
      if (pass->ok[k] == 0) continue;
      const std::size_t i = pass->column[k];
      const double* a = pass->r[k].data();
      for (std::size_t m = 0; m < n; ++m) out[m * p + i] = (a[m] - r0[m]) / pass->offset[k];
    }
  }
  return rollouts;
}

}  // namespace motoflex::detail
