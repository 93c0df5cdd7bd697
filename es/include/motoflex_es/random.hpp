#pragma once

#include <cstdint>

namespace motoflex_es {

// What a random stream is used for. A stream is keyed by (seed, generation, individual,
// purpose), so two uses never share draws and a draw never depends on how many draws another
// use took. The numeric values are part of the checkpoint format: never renumber them.
enum class Purpose : std::uint64_t {
  kInitialPopulation = 1,  // initial individuals of a population-based strategy
  kParentChoice = 2,       // which parents an offspring is recombined from
  kRecombination = 3,      // discrete recombination: which parent gives each coordinate
  kStepSizeMutation = 4,   // log-normal mutation of the step sizes
  kObjectMutation = 5,     // Gaussian mutation of the object parameters
  kCmaSample = 6,          // CMA-ES standard normal vectors z_k
  kRestart = 7,            // IPOP restart: new initial mean
  kNloptSeed = 8,          // seed handed to nlopt::srand
  kTest = 1000,            // reserved for tests and example problems
};

// SplitMix64's finaliser (Steele, Lea, Flood 2014): a bijection on 64 bits in which every output
// bit depends on every input bit. mix64(0x9E3779B97F4A7C15) == 0xE220A8397B1DCDAF, the first
// output of SplitMix64 seeded with 0.
std::uint64_t mix64(std::uint64_t value);

// A counter-based random stream. Draw i is mix64(key + (i + 1)·γ), γ = 0x9E3779B97F4A7C15, where
// the key is a hash of (seed, generation, individual, purpose). A stream's whole state is its
// key and counter: the same keys give the same draws on any thread, in any order, after a
// resume. Uniform draws use integer arithmetic and one exact conversion and are bit-identical on
// every platform; normal() also calls std::log, std::sqrt and std::cos and is bit-identical
// wherever the maths library is the same (every process of one build, every MPI rank of a
// homogeneous cluster). No std::*_distribution is used anywhere: their algorithms are
// implementation-defined.
class RandomStream {
 public:
  RandomStream(std::uint64_t seed, std::uint64_t generation, std::uint64_t individual,
               Purpose purpose);

  // The next 64 uniformly distributed bits.
  std::uint64_t next_u64();
  // Uniform on [0, 1): 53 random bits, every multiple of 2^-53 equally likely.
  double uniform();
  // Uniform integer in [0, n) without modulo bias (rejection of the top remainder); n > 0.
  std::uint64_t uniform_index(std::uint64_t n);
  // Standard normal by Box–Muller (cosine branch only); consumes exactly two draws so the
  // value of a draw never depends on whether an odd or even number of normals came before it.
  double normal();

  std::uint64_t key() const { return key_; }
  // Number of 64-bit draws taken so far; set_counter() replays from any position.
  std::uint64_t counter() const { return counter_; }
  void set_counter(std::uint64_t counter) { counter_ = counter; }

 private:
  std::uint64_t key_;
  std::uint64_t counter_ = 0;
};

}  // namespace motoflex_es
