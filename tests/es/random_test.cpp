#include "motoflex_es/random.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

namespace motoflex_es {
namespace {

constexpr int kDraws = 100000;

TEST(EsRandomTest, MixMatchesReferenceSplitMix64) {
  // SplitMix64 seeded with 0 outputs mix(γ), mix(2γ), mix(3γ) (Vigna's reference values).
  constexpr std::uint64_t kGamma = 0x9E3779B97F4A7C15ULL;
  EXPECT_EQ(motoflex::mix64(kGamma), 0xE220A8397B1DCDAFULL);
  EXPECT_EQ(motoflex::mix64(2 * kGamma), 0x6E789E6AA1B965F4ULL);
  EXPECT_EQ(motoflex::mix64(3 * kGamma), 0x06C45D188009454FULL);
}

TEST(EsRandomTest, KnownAnswersArePinned) {
  // Computed independently with Python integers from the documented construction. If these
  // change, every saved checkpoint stops resuming bit-identically.
  motoflex::RandomStream stream = es_stream(42, 7, 3, Purpose::kTest);
  // Draw i is mix64(hash + (i + 1)·γ): the core stream holds hash + γ as its key.
  EXPECT_EQ(stream.key(), 0x7184CAD65BA29514ULL + 0x9E3779B97F4A7C15ULL);
  EXPECT_EQ(stream.next_u64(), 0xAE7BAF11ABBD4B2CULL);
  EXPECT_EQ(stream.next_u64(), 0xB66700517D31C6A4ULL);
  EXPECT_EQ(stream.next_u64(), 0xABD1D463B3675872ULL);
  motoflex::RandomStream uniform_stream = es_stream(42, 7, 3, Purpose::kTest);
  EXPECT_EQ(uniform_stream.uniform(), 0.6815747659818402);
}

TEST(EsRandomTest, EveryKeyComponentSelectsItsOwnStream) {
  const std::uint64_t reference = es_stream(1, 2, 3, Purpose::kTest).next_u64();
  EXPECT_EQ(es_stream(1, 2, 3, Purpose::kTest).next_u64(), reference);
  EXPECT_NE(es_stream(9, 2, 3, Purpose::kTest).next_u64(), reference);
  EXPECT_NE(es_stream(1, 9, 3, Purpose::kTest).next_u64(), reference);
  EXPECT_NE(es_stream(1, 2, 9, Purpose::kTest).next_u64(), reference);
  EXPECT_NE(es_stream(1, 2, 3, Purpose::kCmaSample).next_u64(), reference);
  // Swapping two keys must not give the same stream.
  EXPECT_NE(es_stream(2, 1, 3, Purpose::kTest).next_u64(),
            es_stream(1, 2, 3, Purpose::kTest).next_u64());
}

TEST(EsRandomTest, CounterReplaysAnyPosition) {
  motoflex::RandomStream stream = es_stream(5, 0, 0, Purpose::kTest);
  std::vector<std::uint64_t> draws;
  for (int i = 0; i < 10; ++i) draws.push_back(stream.next_u64());
  EXPECT_EQ(stream.counter(), 10u);
  motoflex::RandomStream replay = es_stream(5, 0, 0, Purpose::kTest);
  replay.set_counter(6);
  for (int i = 6; i < 10; ++i) EXPECT_EQ(replay.next_u64(), draws[static_cast<std::size_t>(i)]);
}

TEST(EsRandomTest, UniformAndNormalHaveTheRightMoments) {
  motoflex::RandomStream stream = es_stream(11, 0, 0, Purpose::kTest);
  double sum = 0.0, sum_squares = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double u = stream.uniform();
    ASSERT_GE(u, 0.0);
    ASSERT_LT(u, 1.0);
    sum += u;
    sum_squares += u * u;
  }
  EXPECT_NEAR(sum / kDraws, 0.5, 0.005);
  EXPECT_NEAR(sum_squares / kDraws - 0.25, 1.0 / 12.0, 0.003);

  motoflex::RandomStream normals = es_stream(12, 0, 0, Purpose::kTest);
  sum = sum_squares = 0.0;
  double sum_fourth = 0.0;
  for (int i = 0; i < kDraws; ++i) {
    const double z = normals.normal_libm();
    ASSERT_TRUE(std::isfinite(z));
    sum += z;
    sum_squares += z * z;
    sum_fourth += z * z * z * z;
  }
  EXPECT_EQ(normals.counter(), 2u * kDraws);  // exactly two draws per normal
  EXPECT_NEAR(sum / kDraws, 0.0, 0.015);
  EXPECT_NEAR(sum_squares / kDraws, 1.0, 0.02);
  EXPECT_NEAR(sum_fourth / kDraws, 3.0, 0.15);  // Gaussian kurtosis
}

TEST(EsRandomTest, UniformIndexCoversTheRangeEvenly) {
  motoflex::RandomStream stream = es_stream(13, 0, 0, Purpose::kTest);
  constexpr std::uint64_t kRange = 7;
  std::vector<int> counts(kRange, 0);
  for (int i = 0; i < kDraws; ++i) {
    const std::uint64_t index = stream.uniform_index(kRange);
    ASSERT_LT(index, kRange);
    ++counts[index];
  }
  for (int count : counts) EXPECT_NEAR(count, kDraws / 7.0, 5.0 * std::sqrt(kDraws / 7.0));
  EXPECT_EQ(stream.uniform_index(1), 0u);
}

}  // namespace
}  // namespace motoflex_es
