#include "motoflex/core/text_hash.hpp"

#include <cstdint>
#include <cstdio>

#include "motoflex/core/random_stream.hpp"

namespace motoflex {

std::string hash_text(std::string_view text) {
  std::uint64_t hash = 0xcbf29ce484222325ULL;  // FNV-1a 64 offset basis
  for (const char c : text) {
    hash ^= static_cast<unsigned char>(c);
    hash *= 0x100000001b3ULL;  // FNV-1a 64 prime
  }
  hash = mix64(hash ^ static_cast<std::uint64_t>(text.size()));
  char digits[17];
  std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(hash));
  return digits;
}

}  // namespace motoflex
