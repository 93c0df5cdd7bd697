#include "motoflex/report/frequency_response.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "json_numbers.hpp"

namespace motoflex::report {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr std::size_t kMinSamples = 64;
constexpr int kSignificant = 5;  // digits in the JSON: far below what a Bode plot resolves

// Samples before the first non-finite value in any of the series.
std::size_t usable_span(const std::vector<const std::vector<double>*>& series, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    for (const auto* s : series) {
      if (!std::isfinite((*s)[i])) return i;
    }
  }
  return n;
}

struct UniformGrid {
  double dt_s = 0.0;
  std::size_t samples = 0;
};

// The median step of the first `n` times, and how many such steps fit into their span.
UniformGrid uniform_grid(const std::vector<double>& time_s, std::size_t n) {
  std::vector<double> steps;
  for (std::size_t i = 1; i < n; ++i) steps.push_back(time_s[i] - time_s[i - 1]);
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                   steps.end());
  const double dt_s = steps[steps.size() / 2];
  if (!(dt_s > 0.0)) return {};
  const double span_s = time_s[n - 1] - time_s[0];
  return {dt_s, static_cast<std::size_t>(std::floor(span_s / dt_s + 1e-9)) + 1};
}

// `values` (at `time_s`, the first n) at t0 + k·dt by linear interpolation.
std::vector<double> resampled(const std::vector<double>& time_s, const std::vector<double>& values,
                              std::size_t n, const UniformGrid& grid) {
  std::vector<double> out(grid.samples);
  std::size_t i = 0;
  for (std::size_t k = 0; k < grid.samples; ++k) {
    const double t = time_s[0] + static_cast<double>(k) * grid.dt_s;
    while (i + 2 < n && time_s[i + 1] <= t) ++i;
    const double w = std::clamp((t - time_s[i]) / (time_s[i + 1] - time_s[i]), 0.0, 1.0);
    out[k] = values[i] + w * (values[i + 1] - values[i]);
  }
  return out;
}

// Cross- and auto-spectra of one input against several outputs at one frequency, summed over
// the Welch segments.
struct Spectra {
  double input = 0.0;                       // S_xx
  std::vector<double> output;               // S_yy per output
  std::vector<std::complex<double>> cross;  // S_xy per output
};

// The Welch segments of `x`: `segments` of length L overlapping by half, each mean-removed
// and Hann-windowed (`window`), once for every frequency.
std::vector<std::vector<double>> windowed_segments(const std::vector<double>& x, std::size_t L,
                                                   std::size_t segments,
                                                   const std::vector<double>& window) {
  std::vector<std::vector<double>> out(segments, std::vector<double>(L));
  for (std::size_t k = 0; k < segments; ++k) {
    const std::size_t begin = k * (L / 2);
    double mean = 0.0;
    for (std::size_t n = 0; n < L; ++n) mean += x[begin + n];
    mean /= static_cast<double>(L);
    for (std::size_t n = 0; n < L; ++n) out[k][n] = window[n] * (x[begin + n] - mean);
  }
  return out;
}

// DFT of a windowed segment at `omega` (rad per sample).
std::complex<double> dft(const std::vector<double>& segment, double omega) {
  const std::complex<double> step = std::polar(1.0, -omega);
  std::complex<double> rotation = 1.0;
  std::complex<double> sum = 0.0;
  for (const double v : segment) {
    sum += v * rotation;
    rotation *= step;
  }
  return sum;
}

// Segments of the input (`input[k]`) and of each output (`outputs[o][k]`).
Spectra welch_spectra(const std::vector<std::vector<double>>& input,
                      const std::vector<std::vector<std::vector<double>>>& outputs, double omega) {
  Spectra s;
  s.output.assign(outputs.size(), 0.0);
  s.cross.assign(outputs.size(), 0.0);
  for (std::size_t k = 0; k < input.size(); ++k) {
    const std::complex<double> x = dft(input[k], omega);
    s.input += std::norm(x);
    for (std::size_t o = 0; o < outputs.size(); ++o) {
      const std::complex<double> y = dft(outputs[o][k], omega);
      s.output[o] += std::norm(y);
      s.cross[o] += std::conj(x) * y;
    }
  }
  return s;
}

// Adds the multiple of 360° that keeps each phase within 180° of the one before it.
void unwrap(std::vector<double>& phase_deg) {
  for (std::size_t i = 1; i < phase_deg.size(); ++i) {
    phase_deg[i] -= 360.0 * std::round((phase_deg[i] - phase_deg[i - 1]) / 360.0);
  }
}

// The responses of every output to the input, on one grid; empty when the data cannot give one.
std::vector<FrequencyResponse> estimate(const std::vector<double>& time_s,
                                        const std::vector<double>& input,
                                        const std::vector<const std::vector<double>*>& outputs,
                                        const FrequencyResponseOptions& options) {
  std::vector<const std::vector<double>*> all{&input};
  all.insert(all.end(), outputs.begin(), outputs.end());
  std::size_t n = std::min(time_s.size(), input.size());
  for (const auto* o : outputs) n = std::min(n, o->size());
  n = usable_span(all, n);
  if (n < kMinSamples) return {};
  const UniformGrid grid = uniform_grid(time_s, n);
  const std::size_t segments = std::max<std::size_t>(options.segments, 1);
  // K segments of length L overlapping by half cover (K + 1)·L/2 samples.
  const std::size_t L = 2 * grid.samples / (segments + 1);
  if (grid.samples < kMinSamples || L < 16 || options.points < 2) return {};
  const std::vector<double> x = resampled(time_s, input, n, grid);
  const auto [low, high] = std::minmax_element(x.begin(), x.end());
  if (!(*high - *low > 1e-12 * std::max(1.0, std::max(std::abs(*low), std::abs(*high))))) {
    return {};  // a constant command excites nothing
  }
  std::vector<double> window(L);
  for (std::size_t i = 0; i < L; ++i) {
    window[i] = 0.5 - 0.5 * std::cos(2.0 * std::numbers::pi * static_cast<double>(i) /
                                     static_cast<double>(L - 1));
  }
  const auto x_segments = windowed_segments(x, L, segments, window);
  std::vector<std::vector<std::vector<double>>> y_segments;
  y_segments.reserve(outputs.size());
  for (const auto* o : outputs) {
    y_segments.push_back(windowed_segments(resampled(time_s, *o, n, grid), L, segments, window));
  }
  const double f_low_hz = 2.0 / (static_cast<double>(L) * grid.dt_s);
  const double f_high_hz = options.max_fraction_of_nyquist * 0.5 / grid.dt_s;
  if (!(f_low_hz < f_high_hz)) return {};
  std::vector<FrequencyResponse> out(outputs.size());
  for (std::size_t p = 0; p < options.points; ++p) {
    const double f_hz =
        f_low_hz * std::pow(f_high_hz / f_low_hz,
                            static_cast<double>(p) / static_cast<double>(options.points - 1));
    const Spectra s =
        welch_spectra(x_segments, y_segments, 2.0 * std::numbers::pi * f_hz * grid.dt_s);
    for (std::size_t o = 0; o < outputs.size(); ++o) {
      const std::complex<double> h = s.input > 0.0 ? s.cross[o] / s.input : kNaN;
      const double denominator = s.input * s.output[o];
      out[o].frequency_hz.push_back(f_hz);
      out[o].gain_db.push_back(20.0 * std::log10(std::abs(h)));
      out[o].phase_deg.push_back(std::arg(h) * 180.0 / std::numbers::pi);
      out[o].coherence.push_back(denominator > 0.0 ? std::norm(s.cross[o]) / denominator : 0.0);
    }
  }
  for (auto& response : out) unwrap(response.phase_deg);
  return out;
}

double wrapped_deg(double degrees) {
  return degrees - 360.0 * std::round(degrees / 360.0);
}

nlohmann::json response_json(const FrequencyResponse& response) {
  return {{"gain_db", detail::numbers_json(response.gain_db, kSignificant)},
          {"phase_deg", detail::numbers_json(response.phase_deg, kSignificant)},
          {"coherence", detail::numbers_json(response.coherence, kSignificant)}};
}

}  // namespace

std::optional<FrequencyResponse> estimate_frequency_response(
    const std::vector<double>& time_s, const std::vector<double>& input,
    const std::vector<double>& output, const FrequencyResponseOptions& options) {
  std::vector<FrequencyResponse> responses = estimate(time_s, input, {&output}, options);
  if (responses.empty()) return std::nullopt;
  return std::move(responses.front());
}

std::optional<FrequencyComparison> compare_frequency_responses(
    const std::vector<double>& time_s, const std::vector<double>& command,
    const std::vector<double>& measured, const std::vector<double>& simulated,
    const FrequencyResponseOptions& options) {
  std::vector<FrequencyResponse> responses =
      estimate(time_s, command, {&measured, &simulated}, options);
  if (responses.empty()) return std::nullopt;
  FrequencyComparison out;
  out.measured = std::move(responses[0]);
  out.simulated = std::move(responses[1]);
  double gain_sum = 0.0, phase_sum = 0.0;
  out.measured_peak_db = out.simulated_peak_db = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < out.measured.frequency_hz.size(); ++i) {
    const double gm = out.measured.gain_db[i], gs = out.simulated.gain_db[i];
    if (!(out.measured.coherence[i] >= kMinCoherence &&
          out.simulated.coherence[i] >= kMinCoherence && std::isfinite(gm) && std::isfinite(gs))) {
      continue;
    }
    ++out.coherent_points;
    gain_sum += (gm - gs) * (gm - gs);
    const double dp = wrapped_deg(out.measured.phase_deg[i] - out.simulated.phase_deg[i]);
    phase_sum += dp * dp;
    if (gm > out.measured_peak_db) {
      out.measured_peak_db = gm;
      out.measured_peak_hz = out.measured.frequency_hz[i];
    }
    if (gs > out.simulated_peak_db) {
      out.simulated_peak_db = gs;
      out.simulated_peak_hz = out.simulated.frequency_hz[i];
    }
  }
  if (out.coherent_points == 0) {
    out.gain_rms_db = out.phase_rms_deg = kNaN;
    out.measured_peak_hz = out.measured_peak_db = out.simulated_peak_hz = out.simulated_peak_db =
        kNaN;
  } else {
    const double count = static_cast<double>(out.coherent_points);
    out.gain_rms_db = std::sqrt(gain_sum / count);
    out.phase_rms_deg = std::sqrt(phase_sum / count);
  }
  return out;
}

nlohmann::json frequency_comparison_json(const FrequencyComparison& comparison) {
  return {{"f_hz", detail::numbers_json(comparison.measured.frequency_hz, kSignificant)},
          {"measured", response_json(comparison.measured)},
          {"simulated", response_json(comparison.simulated)},
          {"coherent_points", comparison.coherent_points},
          {"gain_rms_db", detail::number_json(comparison.gain_rms_db, kSignificant)},
          {"phase_rms_deg", detail::number_json(comparison.phase_rms_deg, kSignificant)},
          {"measured_peak_hz", detail::number_json(comparison.measured_peak_hz, kSignificant)},
          {"measured_peak_db", detail::number_json(comparison.measured_peak_db, kSignificant)},
          {"simulated_peak_hz", detail::number_json(comparison.simulated_peak_hz, kSignificant)},
          {"simulated_peak_db", detail::number_json(comparison.simulated_peak_db, kSignificant)}};
}

}  // namespace motoflex::report
