#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>

#include "motoflex/core/text_hash.hpp"

namespace motoflex_es {

// A checkpoint or saved strategy state that cannot be used: unreadable, truncated or corrupt,
// of another format version, written for another configuration, or for another strategy. The
// message is one line that starts with the file (or "strategy state") and says what is wrong.
class CheckpointError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Version of the checkpoint file layout below; bumped on any incompatible change, including a
// change to what a strategy's saved state means.
inline constexpr int kCheckpointFormatVersion = 1;

// What a checkpoint holds. On disk it is one JSON object
//   { "format": "motoflex_es.checkpoint", "format_version": 1, "config_hash": "...",
//     "payload_hash": "<16 hex digits>", "payload": { "strategy": {...}, "extra": {...} } }
// where payload_hash is hash_text(payload.dump()): nlohmann writes every double in its
// shortest round-trip form, so parsing and dumping again reproduces the text and the hash, and a
// flipped digit anywhere in the payload is caught.
struct Checkpoint {
  // Identifies the configuration of the run (see config_hash()); a resume with another
  // configuration is refused.
  std::string config_hash;
  // Strategy::save_state().
  nlohmann::json strategy_state;
  // The caller's own state (elapsed time, rows already logged, ...); any JSON value.
  nlohmann::json extra = nlohmann::json::object();
};

// motoflex::hash_text(config.dump()): the same configuration gives the same hash on every run.
std::string config_hash(const nlohmann::json& config);

// Writes the checkpoint so that a crash leaves either the previous file or the new one, never a
// torn one: the text goes to a temporary file in the same folder, which is fsync'ed and renamed
// over `path`, and then the folder is fsync'ed. Throws CheckpointError (and removes the
// temporary file) if any step fails.
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

// Reads and validates a checkpoint: readable, complete JSON, the right format and version, an
// intact payload, and config_hash == expected_config_hash. Anything else throws CheckpointError
// with a one-line message, e.g.
//   "run.ckpt: checkpoint was written for config 1a2b..., this configuration is 3c4d...".
Checkpoint read_checkpoint(const std::string& path, const std::string& expected_config_hash);
// The same validation on text already in memory; `source` names it in error messages.
Checkpoint parse_checkpoint(std::string_view text, const std::string& expected_config_hash,
                            const std::string& source);

}  // namespace motoflex_es
