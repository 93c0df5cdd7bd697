#include "motoflex_es/checkpoint.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex_es/version.hpp"

namespace motoflex_es {

using motoflex::hash_text;
namespace {

constexpr const char* kFormatName = "motoflex_es.checkpoint";

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw CheckpointError(where + ": " + what);
}

}  // namespace

std::string config_hash(const nlohmann::json& config) {
  return hash_text(config.dump());
}

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint) {
  const nlohmann::json payload = {{"strategy", checkpoint.strategy_state},
                                  {"extra", checkpoint.extra}};
  const nlohmann::json document = {
      {"format", kFormatName},
      {"format_version", kCheckpointFormatVersion},
      {"library_version", version()},
      {"config_hash", checkpoint.config_hash},
      {"payload_hash", hash_text(payload.dump())},
      {"payload", payload},
  };
  try {
    motoflex::write_file_atomically(path, document.dump(1) + "\n");
  } catch (const motoflex::IoError&) {
    throw;  // a full disk is the machine's problem, not the checkpoint's (exit code 3)
  } catch (const motoflex::InputError& error) {
    throw CheckpointError(error.what());
  }
}

Checkpoint parse_checkpoint(std::string_view text, const std::string& expected_config_hash,
                            const std::string& source) {
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    fail(source,
         std::string("checkpoint is not valid JSON (truncated or corrupt): ") + error.what());
  }
  const auto field = [&](const char* name) -> const nlohmann::json& {
    if (!document.is_object() || !document.contains(name)) {
      fail(source, std::string("checkpoint has no '") + name + "' field (not a checkpoint?)");
    }
    return document[name];
  };
  if (field("format") != kFormatName) fail(source, "not a motoflex_es checkpoint");
  const nlohmann::json& version_field = field("format_version");
  if (!version_field.is_number_integer() ||
      version_field.get<long long>() != kCheckpointFormatVersion) {
    fail(source, "checkpoint format version " + version_field.dump() +
                     ", this build reads version " + std::to_string(kCheckpointFormatVersion));
  }
  const nlohmann::json& payload = field("payload");
  const nlohmann::json& payload_hash = field("payload_hash");
  if (!payload.is_object() || !payload_hash.is_string() ||
      payload_hash.get<std::string>() != hash_text(payload.dump()) ||
      !payload.contains("strategy") || !payload.contains("extra")) {
    fail(source, "checkpoint payload is corrupt (its hash does not match)");
  }
  const nlohmann::json& saved_hash = field("config_hash");
  if (!saved_hash.is_string()) fail(source, "checkpoint config_hash is not a string");
  if (saved_hash.get<std::string>() != expected_config_hash) {
    fail(source, "checkpoint was written for config " + saved_hash.get<std::string>() +
                     ", this configuration is " + expected_config_hash);
  }
  Checkpoint checkpoint;
  checkpoint.config_hash = saved_hash.get<std::string>();
  checkpoint.strategy_state = payload["strategy"];
  checkpoint.extra = payload["extra"];
  return checkpoint;
}

Checkpoint read_checkpoint(const std::string& path, const std::string& expected_config_hash) {
  std::ifstream in(path, std::ios::binary);
  if (!in) fail(path, std::string("cannot open checkpoint: ") + std::strerror(errno));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) fail(path, "cannot read checkpoint");
  return parse_checkpoint(text.str(), expected_config_hash, path);
}

}  // namespace motoflex_es
