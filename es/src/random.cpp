#include "motoflex_es/random.hpp"

#include <cmath>
#include <numbers>

namespace motoflex_es {
namespace {

// 2^64/φ, odd: i·γ runs through all 64-bit values before repeating.
constexpr std::uint64_t kGamma = 0x9E3779B97F4A7C15ULL;

// Folds one key into the running hash; the extra mix makes the order of the keys matter.
std::uint64_t fold(std::uint64_t hash, std::uint64_t key) {
  return mix64(hash ^ mix64(key + kGamma));
}

}  // namespace

std::uint64_t mix64(std::uint64_t value) {
  value = (value ^ (value >> 30)) * 0xBF58476D1CE4E5B9ULL;
  value = (value ^ (value >> 27)) * 0x94D049BB133111EBULL;
  return value ^ (value >> 31);
}

RandomStream::RandomStream(std::uint64_t seed, std::uint64_t generation, std::uint64_t individual,
                           Purpose purpose) {
  // A fixed domain tag first, so that an es stream never equals a stream of another library
  // that happens to hash the same four numbers.
  std::uint64_t hash = mix64(0x6d6f746f666c6578ULL);  // "motoflex"
  hash = fold(hash, seed);
  hash = fold(hash, generation);
  hash = fold(hash, individual);
  hash = fold(hash, static_cast<std::uint64_t>(purpose));
  key_ = hash;
}

std::uint64_t RandomStream::next_u64() {
  ++counter_;
  return mix64(key_ + counter_ * kGamma);
}

double RandomStream::uniform() {
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

double RandomStream::normal() {
  const double u1 = 1.0 - uniform();  // (0, 1]: log(u1) is finite
  const double u2 = uniform();
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

}  // namespace motoflex_es
