#include "motoflex_es/random.hpp"

namespace motoflex_es {
namespace {

constexpr std::uint64_t kGamma = 0x9E3779B97F4A7C15ULL;

std::uint64_t fold(std::uint64_t hash, std::uint64_t key) {
  return motoflex::mix64(hash ^ motoflex::mix64(key + kGamma));
}

}  // namespace

motoflex::RandomStream es_stream(std::uint64_t seed, std::uint64_t generation,
                                 std::uint64_t individual, Purpose purpose) {
  // A fixed domain tag first, so that an es stream never equals a stream of another use that
  // happens to hash the same four numbers.
  std::uint64_t hash = motoflex::mix64(0x6d6f746f666c6578ULL);  // "motoflex"
  hash = fold(hash, seed);
  hash = fold(hash, generation);
  hash = fold(hash, individual);
  hash = fold(hash, static_cast<std::uint64_t>(purpose));
  // Draw i of the es streams has always been mix64(hash + (i + 1)·γ).
  return motoflex::RandomStream::with_key(hash + kGamma);
}

}  // namespace motoflex_es
