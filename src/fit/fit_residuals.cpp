#include "fit_residuals.hpp"

#include <algorithm>
#include <cmath>

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

std::uint64_t FitResiduals::jacobian(const std::vector<double>& x, const std::vector<double>& r0,
                                     double step, std::vector<double>& out) const {
  const std::size_t p = dimension(), n = size_;
  const std::vector<double> lower = config_.space->lower(), upper = config_.space->upper();
  // Two points per coordinate (x + h, x − h); a side outside the bounds is skipped.
  std::vector<std::vector<double>> points(2 * p, x);
  std::vector<char> inside(2 * p, 0);
  std::vector<double> h(p);
  for (std::size_t i = 0; i < p; ++i) {
    h[i] = step * (upper[i] - lower[i]);
    points[2 * i][i] = x[i] + h[i];
    points[2 * i + 1][i] = x[i] - h[i];
    inside[2 * i] = points[2 * i][i] <= upper[i] ? 1 : 0;
    inside[2 * i + 1] = points[2 * i + 1][i] >= lower[i] ? 1 : 0;
  }
  std::vector<std::vector<double>> r(2 * p);
  std::vector<char> ok(2 * p, 0);
  ensure_ode_ready();  // the process-wide part, before the workers start
  // Each point is independent (its logs simulated serially), so the order of the workers does
  // not change any number.
#pragma omp parallel for schedule(dynamic, 1) num_threads(threads_)
  for (long q = 0; q < static_cast<long>(2 * p); ++q) {
    const auto s = static_cast<std::size_t>(q);
    if (!inside[s]) continue;
    ensure_ode_ready();  // this worker's own ODE data
    FitResiduals serial(*this);
    serial.threads_ = 1;
    r[s].resize(n);
    ok[s] = serial.evaluate(points[s], r[s].data()) ? 1 : 0;
  }
  std::uint64_t rollouts = 0;
  for (const char in : inside) rollouts += in ? 1 : 0;
  out.assign(n * p, 0.0);
  for (std::size_t i = 0; i < p; ++i) {
    const bool plus = ok[2 * i] != 0, minus = ok[2 * i + 1] != 0;
    if (!plus && !minus) continue;
    const double* a = plus ? r[2 * i].data() : r0.data();
    const double* b = minus ? r[2 * i + 1].data() : r0.data();
    const double width = (plus ? h[i] : 0.0) + (minus ? h[i] : 0.0);
    for (std::size_t k = 0; k < n; ++k) out[k * p + i] = (a[k] - b[k]) / width;
  }
  return rollouts;
}

}  // namespace motoflex::detail
