// The frequency-response estimate against systems whose response is known in closed form: a
// second-order servo (gain, phase and resonance), a pure delay (linear phase), a log with
// irregular steps, and the cases with no answer (constant command, too few samples, a
// simulation that stops early).

#include "motoflex/report/frequency_response.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

namespace motoflex::report {
namespace {

constexpr double kPi = std::numbers::pi;

// A broadband command: 150 sines at 0.05 Hz spacing (0.05–7.5 Hz), seeded phases, 0.1 rad each.
struct Multisine {
  std::vector<double> frequency_hz, phase_rad;
  explicit Multisine(unsigned seed) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> phase(0.0, 2.0 * kPi);
    for (int k = 1; k <= 150; ++k) {
      frequency_hz.push_back(0.05 * k);
      phase_rad.push_back(phase(random));
    }
  }
  double operator()(double t) const {
    double u = 0.0;
    for (std::size_t k = 0; k < frequency_hz.size(); ++k) {
      u += 0.1 * std::sin(2.0 * kPi * frequency_hz[k] * t + phase_rad[k]);
    }
    return u;
  }
};

// y'' = ω²(u − y) − 2ζω·y', from rest, by RK4 at dt/20, sampled at `time_s`.
std::vector<double> second_order(const Multisine& u, const std::vector<double>& time_s,
                                 double natural_hz, double damping) {
  const double w = 2.0 * kPi * natural_hz;
  const auto accel = [&](double t, double y, double v) {
    return w * w * (u(t) - y) - 2.0 * damping * w * v;
  };
  std::vector<double> out;
  double t = 0.0, y = 0.0, v = 0.0;
  for (const double sample_t : time_s) {
    while (t < sample_t - 1e-12) {
      const double h = std::min(2.5e-4, sample_t - t);
      const double k1y = v, k1v = accel(t, y, v);
      const double k2y = v + 0.5 * h * k1v, k2v = accel(t + 0.5 * h, y + 0.5 * h * k1y, k2y);
      const double k3y = v + 0.5 * h * k2v, k3v = accel(t + 0.5 * h, y + 0.5 * h * k2y, k3y);
      const double k4y = v + h * k3v, k4v = accel(t + h, y + h * k3y, k4y);
      y += h / 6.0 * (k1y + 2.0 * k2y + 2.0 * k3y + k4y);
      v += h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
      t += h;
    }
    out.push_back(y);
  }
  return out;
}

std::complex<double> second_order_response(double f_hz, double natural_hz, double damping) {
  const double w = 2.0 * kPi * f_hz, wn = 2.0 * kPi * natural_hz;
  return wn * wn / std::complex<double>(wn * wn - w * w, 2.0 * damping * wn * w);
}

std::vector<double> grid(double dt_s, double duration_s) {
  std::vector<double> t;
  for (double s = 0.0; s <= duration_s + 1e-9; s += dt_s) t.push_back(s);
  return t;
}

std::vector<double> sampled(const Multisine& u, const std::vector<double>& time_s,
                            double delay_s = 0.0) {
  std::vector<double> out;
  out.reserve(time_s.size());
  for (const double t : time_s) out.push_back(u(t - delay_s));
  return out;
}

TEST(FrequencyResponseTest, ASecondOrderServoGivesItsGainPhaseAndResonance) {
  const Multisine u(1);
  const std::vector<double> t = grid(0.005, 40.0);
  const double natural_hz = 3.0, damping = 0.15;
  const auto response =
      estimate_frequency_response(t, sampled(u, t), second_order(u, t, natural_hz, damping));
  ASSERT_TRUE(response);
  std::size_t checked = 0;
  double peak_db = -1e9, peak_hz = 0.0;
  for (std::size_t i = 0; i < response->frequency_hz.size(); ++i) {
    const double f = response->frequency_hz[i];
    if (f < 0.3 || f > 7.0) continue;  // inside the multisine's band
    const std::complex<double> h = second_order_response(f, natural_hz, damping);
    // The Hann window (10 s segments here) smooths the resonance peak by about half a dB.
    EXPECT_NEAR(response->gain_db[i], 20.0 * std::log10(std::abs(h)), 0.75) << f << " Hz";
    EXPECT_NEAR(response->phase_deg[i], std::arg(h) * 180.0 / kPi, 4.0) << f << " Hz";
    EXPECT_GT(response->coherence[i], 0.98) << f << " Hz";
    if (response->gain_db[i] > peak_db) {
      peak_db = response->gain_db[i];
      peak_hz = f;
    }
    ++checked;
  }
  EXPECT_GT(checked, 20u);
  // The peak of |H|: at f_n·sqrt(1 − 2ζ²), 1/(2ζ·sqrt(1 − ζ²)) high (10.5 dB here); the grid's
  // spacing and the window's smoothing put it within 6 % and 1.5 dB.
  EXPECT_NEAR(peak_hz, natural_hz * std::sqrt(1.0 - 2.0 * damping * damping), 0.06 * natural_hz);
  EXPECT_NEAR(peak_db, -20.0 * std::log10(2.0 * damping * std::sqrt(1.0 - damping * damping)), 1.5);
}

TEST(FrequencyResponseTest, APureDelayHasUnitGainAndALinearPhase) {
  const Multisine u(2);
  const std::vector<double> t = grid(0.005, 30.0);
  const double delay_s = 0.04;
  const auto response = estimate_frequency_response(t, sampled(u, t), sampled(u, t, delay_s));
  ASSERT_TRUE(response);
  for (std::size_t i = 0; i < response->frequency_hz.size(); ++i) {
    const double f = response->frequency_hz[i];
    if (f < 0.3 || f > 7.0) continue;
    EXPECT_NEAR(response->gain_db[i], 0.0, 0.3) << f << " Hz";
    EXPECT_NEAR(response->phase_deg[i], -360.0 * f * delay_s, 4.0) << f << " Hz";  // unwrapped
  }
}

TEST(FrequencyResponseTest, IrregularStepsAreResampled) {
  // A servo log's own clock: steps of 5 ms ± 1 ms.
  const Multisine u(3);
  std::mt19937 random(4);
  std::uniform_real_distribution<double> jitter(-0.001, 0.001);
  std::vector<double> t{0.0};
  while (t.back() < 30.0) t.push_back(t.back() + 0.005 + jitter(random));
  const auto response = estimate_frequency_response(t, sampled(u, t), second_order(u, t, 2.0, 0.3));
  ASSERT_TRUE(response);
  for (std::size_t i = 0; i < response->frequency_hz.size(); ++i) {
    const double f = response->frequency_hz[i];
    if (f < 0.3 || f > 7.0) continue;
    const std::complex<double> h = second_order_response(f, 2.0, 0.3);
    EXPECT_NEAR(response->gain_db[i], 20.0 * std::log10(std::abs(h)), 1.0) << f << " Hz";
  }
}

TEST(FrequencyResponseTest, NoAnswerWithoutExcitationOrSamples) {
  const std::vector<double> t = grid(0.01, 10.0);
  const std::vector<double> constant(t.size(), 0.3);
  const Multisine u(5);
  EXPECT_FALSE(estimate_frequency_response(t, constant, sampled(u, t)));
  const std::vector<double> short_t = grid(0.01, 0.5);
  EXPECT_FALSE(estimate_frequency_response(short_t, sampled(u, short_t), sampled(u, short_t)));
}

TEST(FrequencyResponseTest, TheComparisonUsesTheSpanTheSimulationReached) {
  const Multisine u(6);
  const std::vector<double> t = grid(0.005, 40.0);
  const std::vector<double> command = sampled(u, t);
  const std::vector<double> measured = second_order(u, t, 3.0, 0.15);
  // The model: the same servo, 20 % stiffer and better damped; it falls (NaN) at 30 s.
  std::vector<double> simulated = second_order(u, t, 3.6, 0.3);
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (t[i] >= 30.0) simulated[i] = std::nan("");
  }
  const auto same = compare_frequency_responses(t, command, measured, measured);
  ASSERT_TRUE(same);
  EXPECT_GT(same->coherent_points, 20u);
  EXPECT_DOUBLE_EQ(same->gain_rms_db, 0.0);
  EXPECT_DOUBLE_EQ(same->phase_rms_deg, 0.0);
  const auto other = compare_frequency_responses(t, command, measured, simulated);
  ASSERT_TRUE(other);
  // The grid ends where the simulation did: two periods per segment of 30 s, not 40 s.
  EXPECT_NEAR(other->measured.frequency_hz.front(), 2.0 / (2.0 * 30.0 / 8.0), 0.01);
  EXPECT_NEAR(other->measured_peak_hz, 3.0 * std::sqrt(1.0 - 2.0 * 0.15 * 0.15), 0.2);
  EXPECT_NEAR(other->simulated_peak_hz, 3.6 * std::sqrt(1.0 - 2.0 * 0.3 * 0.3), 0.3);
  EXPECT_GT(other->gain_rms_db, 1.0);
  EXPECT_GT(other->phase_rms_deg, 5.0);
  const nlohmann::json json = frequency_comparison_json(*other);
  EXPECT_EQ(json["f_hz"].size(), other->measured.frequency_hz.size());
  EXPECT_EQ(json["simulated"]["coherence"].size(), json["f_hz"].size());
  EXPECT_EQ(json["coherent_points"], other->coherent_points);
}

}  // namespace
}  // namespace motoflex::report
