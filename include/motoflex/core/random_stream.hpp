#pragma once

#include <cstdint>
#include <initializer_list>

namespace motoflex {

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix whose output bits
// each depend on every input bit. Exposed so tests can pin it to the reference values.
std::uint64_t mix64(std::uint64_t value);

// A counter-based random stream: the i-th 64-bit draw is mix64(key + i·0x9E3779B97F4A7C15),
// where the key is a hash of the stream's keys, e.g. {run seed, robot, purpose}. A draw
// therefore depends only on the keys and its index, never on which thread made it or what other
// streams did before, so a result is the same for 1 or N threads and after a resume from a
// saved counter(). next_u64() and uniform() use only integer arithmetic and an exact conversion
// and are bit-identical on every platform and compiler; normal() also goes through std::log,
// std::sqrt and std::cos and is bit-identical wherever the maths library is the same (glibc on
// x86-64 and AArch64 alike), and otherwise agrees to within an ulp or two.
// A stream is a small value: copy it to fork a replay, keep one per consumer.
class RandomStream {
 public:
  // The keys are hashed in order, and their number counts: {1, 2} and {2, 1} and {1, 2, 0} give
  // unrelated streams.
  explicit RandomStream(std::initializer_list<std::uint64_t> keys);
  // A stream whose i-th draw (i = 0, 1, ...) is mix64(key + i·γ): for callers that derive the
  // key themselves (the es library's (seed, generation, individual, purpose) streams).
  static RandomStream with_key(std::uint64_t key);

  // The next 64 uniformly distributed bits.
  std::uint64_t next_u64();
  // Uniform on [0, 1) with 53 random bits (every multiple of 2^-53 equally likely).
  double uniform();
  // Uniform integer in [0, n) without modulo bias (rejection of the top remainder); n > 0.
  std::uint64_t uniform_index(std::uint64_t n);
  // Standard normal (mean 0, variance 1) by Box–Muller (cosine branch only, so a draw's value
  // never depends on how many normals came before it); consumes exactly two draws. Uses
  // motoflex's own log and cos (integer and fma arithmetic only), so it is bit-identical on
  // every platform and C library.
  double normal();
  // The same Box–Muller through the C library's std::log and std::cos: bit-identical wherever
  // the maths library is the same. The es library has drawn its normals this way since its
  // checkpoint format 1; it keeps doing so, so that every saved run resumes and reproduces bit
  // for bit (the two forms differ in the last bits of most draws).
  double normal_libm();

  // How many 64-bit draws have been taken; with set_counter() this is all a checkpoint needs.
  std::uint64_t counter() const { return counter_; }
  std::uint64_t key() const { return key_; }
  void set_counter(std::uint64_t counter) { counter_ = counter; }

 private:
  RandomStream() = default;
  std::uint64_t key_ = 0;
  std::uint64_t counter_ = 0;
};

}  // namespace motoflex
