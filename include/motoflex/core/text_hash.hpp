#pragma once

#include <string>
#include <string_view>

namespace motoflex {

// 64-bit FNV-1a of the bytes, finished with SplitMix64's mixer (mix64) over the hash and the
// length, as 16 lower-case hex digits. Detects accidental change (a config, a log, a
// checkpoint payload), not tampering.
std::string hash_text(std::string_view text);

}  // namespace motoflex
