#include "fit_residuals.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

#include "motoflex/sim/ode_runtime.hpp"
#include "probe_nonlinearity.hpp"

namespace motoflex::detail {

FitResiduals::FitResiduals(const FitConfig& config, int threads)
    : config_(config), threads_(std::max(threads, 1)) {
  const FitnessFunction& f = *config.train;
  for (const FitCase& c : f.cases()) {
    const std::size_t first = first_scored_frame(c, f.options().settle_s);
    const double frames = static_cast<double>(c.commands.frames() - first);
    first_frame_.push_back(first);
    frames_.push_back(c.commands.frames() - first);
    scale_.push_back(1.0 / std::sqrt(std::pow(frames, f.options().m)));
    size_ += (c.commands.frames() - first) * f.channels();
  }
}

std::size_t FitResiduals::dimension() const {
  return config_.space->dimension();
}

std::size_t FitResiduals::channels() const {
  return config_.train->channels();
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
                                     FiniteDifferences scheme,
                                     std::vector<double>* nonlinearity) const {
  const std::size_t p = dimension(), n = size_;
  const std::vector<double> lower = config_.space->lower(), upper = config_.space->upper();
  std::vector<double> h(p);
  for (std::size_t i = 0; i < p; ++i) h[i] = step * (upper[i] - lower[i]);
  // Probe k moves coordinate column[k] by offset[k] (±h); only points within the bounds.
  std::vector<std::size_t> column;
  std::vector<double> offset;
  std::vector<std::vector<double>> points;
  const auto probe = [&](std::size_t i, double sign) {
    const double at = x[i] + sign * h[i];
    if (at > upper[i] || at < lower[i]) return false;
    column.push_back(i);
    offset.push_back(sign * h[i]);
    points.push_back(x);
    points.back()[i] = at;
    return true;
  };
  for (std::size_t i = 0; i < p; ++i) {
    // Central: both sides. Forward: x + h, or x − h where x + h leaves the bounds.
    const bool plus = probe(i, 1.0);
    if (scheme == FiniteDifferences::kCentral || !plus) probe(i, -1.0);
  }
  std::vector<std::vector<double>> r;
  std::vector<char> ok;
  std::uint64_t rollouts = evaluate_points(points, r, ok);
  if (scheme == FiniteDifferences::kForward) {
    // A failed forward probe is retried on the other side, in a second pass.
    points.clear();
    const std::size_t first = column.size();
    for (std::size_t k = 0; k < first; ++k) {
      if (ok[k] == 0) probe(column[k], offset[k] > 0.0 ? -1.0 : 1.0);
    }
    if (!points.empty()) {
      std::vector<std::vector<double>> retry_r;
      std::vector<char> retry_ok;
      rollouts += evaluate_points(points, retry_r, retry_ok);
      r.insert(r.end(), retry_r.begin(), retry_r.end());
      ok.insert(ok.end(), retry_ok.begin(), retry_ok.end());
    }
  }
  // Column i from its completed probes: two give (r_a − r_b)/(offset_a − offset_b), one gives
  // (r − r0)/offset; none leaves the column zero.
  std::vector<std::ptrdiff_t> done(p, -1);
  out.assign(n * p, 0.0);
  if (nonlinearity != nullptr) nonlinearity->assign(p, std::numeric_limits<double>::quiet_NaN());
  for (std::size_t k = 0; k < column.size(); ++k) {
    if (ok[k] == 0) continue;
    const std::size_t i = column[k];
    const double* a = r[k].data();
    if (done[i] < 0) {
      done[i] = static_cast<std::ptrdiff_t>(k);
      for (std::size_t m = 0; m < n; ++m) out[m * p + i] = (a[m] - r0[m]) / offset[k];
      continue;
    }
    const auto b = static_cast<std::size_t>(done[i]);
    const double width = offset[b] - offset[k];
    for (std::size_t m = 0; m < n; ++m) out[m * p + i] = (r[b][m] - a[m]) / width;
    if (nonlinearity != nullptr) {
      // Probe b is x + h (made first), k is x − h.
      (*nonlinearity)[i] = probe_nonlinearity(r[b].data(), a, r0.data(), n);
    }
  }
  return rollouts;
}

}  // namespace motoflex::detail
