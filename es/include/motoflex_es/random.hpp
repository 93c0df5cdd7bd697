#pragma once

#include <cstdint>

#include "motoflex/core/random_stream.hpp"

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

// The one random stream of motoflex (core's counter-based RandomStream), keyed the es way: a
// fixed domain tag, then seed, generation, individual and purpose folded in order. Draw i is
// mix64(key + (i + 1)·γ), γ = 0x9E3779B97F4A7C15. The strategies draw their normals with
// normal_libm() (see random_stream.hpp). No std::*_distribution is used anywhere: their
// algorithms are implementation-defined.
motoflex::RandomStream es_stream(std::uint64_t seed, std::uint64_t generation,
                                 std::uint64_t individual, Purpose purpose);

}  // namespace motoflex_es
