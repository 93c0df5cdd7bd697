#include "motoflex/core/random_stream.hpp"

#include <cmath>
#include <numbers>

namespace motoflex {
namespace {

// 2^64/φ, SplitMix64's increment: odd, so i·γ visits every 64-bit value once, and its bits are
// irregular enough that consecutive counters give unrelated mix64 inputs.
constexpr std::uint64_t kGolden = 0x9E3779B97F4A7C15ULL;

// std::log and std::cos are not required to be correctly rounded, and libraries (and even
// glibc's CPU-dependent variants) differ in the last bit. normal() therefore uses these two
// fixed polynomials, evaluated only with IEEE-exact operations (+, −, ×, ÷, sqrt, and explicit
// std::fma, which no compiler may split or fuse differently), so a draw is the same bits on
// every platform. Both are accurate to a few ulp, far below anything a simulation notices.

// Horner evaluation with explicit fma; coefficients highest power first.
template <int N>
double horner(const double (&coefficients)[N], double x) {
  double sum = coefficients[0];
  for (int i = 1; i < N; ++i) sum = std::fma(sum, x, coefficients[i]);
  return sum;
}

// ln(x) for finite x > 0: x = m·2^e with m in [√½, √2), ln m = 2·atanh(s), s = (m−1)/(m+1),
// |s| < 0.172, and atanh(s)/s = Σ s^2k/(2k+1) converges to 1e-17 in 12 terms.
double portable_log(double x) {
  int exponent = 0;
  double mantissa = std::frexp(x, &exponent);  // exact: mantissa in [0.5, 1)
  if (mantissa < 0.70710678118654752440) {
    mantissa *= 2.0;  // exact
    --exponent;
  }
  const double s = (mantissa - 1.0) / (mantissa + 1.0);
  static constexpr double kAtanhSeries[] = {1.0 / 23, 1.0 / 21, 1.0 / 19, 1.0 / 17,
                                            1.0 / 15, 1.0 / 13, 1.0 / 11, 1.0 / 9,
                                            1.0 / 7,  1.0 / 5,  1.0 / 3,  1.0};
  const double log_mantissa = 2.0 * s * horner(kAtanhSeries, s * s);
  return std::fma(static_cast<double>(exponent), 0.69314718055994530942, log_mantissa);
}

// cos(x) and sin(x) for x in [0, π/4] by Taylor series (last term below 1e-18).
double cos_quarter(double x) {
  // cos x = 1 + y·P(y), y = x², P(y) = −1/2! + y/4! − y²/6! + … ; highest power first.
  static constexpr double kCosSeries[] = {
      -1.0 / 6402373705728000.0,  // −1/18!
      1.0 / 20922789888000.0,     // 1/16!
      -1.0 / 87178291200.0,       // −1/14!
      1.0 / 479001600.0,          // 1/12!
      -1.0 / 3628800.0,           // −1/10!
      1.0 / 40320.0,              // 1/8!
      -1.0 / 720.0,               // −1/6!
      1.0 / 24.0,                 // 1/4!
      -1.0 / 2.0,                 // −1/2!
  };
  const double x2 = x * x;
  return std::fma(x2, horner(kCosSeries, x2), 1.0);
}
double sin_quarter(double x) {
  // sin x = x + x³·Q(y), y = x², Q(y) = −1/3! + y/5! − y²/7! + … ; highest power first.
  static constexpr double kSinSeries[] = {
      -1.0 / 121645100408832000.0,  // −1/19!
      1.0 / 355687428096000.0,      // 1/17!
      -1.0 / 1307674368000.0,       // −1/15!
      1.0 / 6227020800.0,           // 1/13!
      -1.0 / 39916800.0,            // −1/11!
      1.0 / 362880.0,               // 1/9!
      -1.0 / 5040.0,                // −1/7!
      1.0 / 120.0,                  // 1/5!
      -1.0 / 6.0,                   // −1/3!
  };
  const double x2 = x * x;
  return std::fma(x * x2, horner(kSinSeries, x2), x);
}

// cos(2π·u) for u in [0, 1). The reductions use only subtractions that Sterbenz's lemma makes
// exact, so the one rounding before the series is 2π·w with w in [0, 1/8].
double portable_cos_turns(double u) {
  if (u > 0.5) u = 1.0 - u;  // cos is even and 1-periodic in turns
  double sign = 1.0;
  if (u > 0.25) {  // cos(2π·u) = −cos(2π·(½ − u))
    u = 0.5 - u;
    sign = -1.0;
  }
  constexpr double kTwoPi = 6.28318530717958647693;
  if (u > 0.125) return sign * sin_quarter((0.25 - u) * kTwoPi);  // cos(π/2 − y) = sin y
  return sign * cos_quarter(u * kTwoPi);
}

}  // namespace

std::uint64_t mix64(std::uint64_t value) {
  value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ULL;
  value = (value ^ (value >> 27)) * 0x94D049BB133111EBULL;
  return value ^ (value >> 31);
}

RandomStream::RandomStream(std::initializer_list<std::uint64_t> keys) {
  // Start from the key count so that a trailing zero key still changes the stream; then fold
  // each key through the non-linear mix so that the order of the keys matters.
  std::uint64_t key = mix64(keys.size() * kGolden);
  for (std::uint64_t k : keys) key = mix64(key ^ mix64(k + kGolden));
  key_ = key;
}

RandomStream RandomStream::with_key(std::uint64_t key) {
  RandomStream stream;
  stream.key_ = key;
  return stream;
}

std::uint64_t RandomStream::next_u64() {
  // Counter-based: value_i = mix(key + i·γ); the state is the counter alone.
  return mix64(key_ + counter_++ * kGolden);
}

double RandomStream::uniform() {
  // The top 53 bits fill a double's significand exactly; scaling by 2^-53 is exact too.
  return static_cast<double>(next_u64() >> 11) * 0x1.0p-53;
}

std::uint64_t RandomStream::uniform_index(std::uint64_t n) {
  // 2^64 mod n values at the bottom would make small results more likely: reject them.
  const std::uint64_t reject_below = (0 - n) % n;
  while (true) {
    const std::uint64_t draw = next_u64();
    if (draw >= reject_below) return draw % n;
  }
}

double RandomStream::normal_libm() {
  const double u1 = 1.0 - uniform();  // (0, 1]: log(u1) is finite
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

double RandomStream::normal() {
  // Box–Muller with u1 in (0, 1] so that log(u1) is finite. Only the cosine half is used: a
  // cached sine half would make the value of a draw depend on whether an odd or even number of
  // normals came before it.
  const double u1 = 1.0 - uniform();
  const double u2 = uniform();
  return std::sqrt(-2.0 * portable_log(u1)) * portable_cos_turns(u2);
}

}  // namespace motoflex
