#include "motoflex_es/checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "motoflex_es/random.hpp"
#include "motoflex_es/version.hpp"

namespace motoflex_es {
namespace {

constexpr const char* kFormatName = "motoflex_es.checkpoint";

[[noreturn]] void fail(const std::string& where, const std::string& what) {
  throw CheckpointError(where + ": " + what);
}

// Removes the temporary file unless it was renamed into place.
class TemporaryFile {
 public:
  explicit TemporaryFile(std::string path) : path_(std::move(path)) {}
  ~TemporaryFile() {
    if (fd_ >= 0) ::close(fd_);
    if (!path_.empty()) ::unlink(path_.c_str());
  }
  TemporaryFile(const TemporaryFile&) = delete;
  TemporaryFile& operator=(const TemporaryFile&) = delete;

  int fd_ = -1;
  std::string path_;
};

}  // namespace

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

std::string config_hash(const nlohmann::json& config) {
  return hash_text(config.dump());
}

void write_file_atomically(const std::string& path, std::string_view content) {
  const std::filesystem::path target(path);
  if (path.empty() || !target.has_filename()) fail(path, "not a file path");
  const std::string folder = target.has_parent_path() ? target.parent_path().string() : ".";
  static std::atomic<unsigned> counter{0};
  TemporaryFile temporary((std::filesystem::path(folder) /
                           ("." + target.filename().string() + ".tmp-" +
                            std::to_string(::getpid()) + "-" + std::to_string(counter++)))
                              .string());
  temporary.fd_ = ::open(temporary.path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0666);
  if (temporary.fd_ < 0) {
    const int error = errno;
    temporary.path_.clear();  // nothing was created
    fail(path, std::string("cannot create a temporary file: ") + std::strerror(error));
  }
  std::string_view rest = content;
  while (!rest.empty()) {
    const ssize_t written = ::write(temporary.fd_, rest.data(), rest.size());
    if (written < 0) {
      if (errno == EINTR) continue;
      fail(path, std::string("cannot write: ") + std::strerror(errno));
    }
    rest.remove_prefix(static_cast<std::size_t>(written));
  }
  if (::fsync(temporary.fd_) != 0) fail(path, std::string("cannot fsync: ") + std::strerror(errno));
  const int fd = temporary.fd_;
  temporary.fd_ = -1;
  if (::close(fd) != 0) fail(path, std::string("cannot close: ") + std::strerror(errno));
  if (::rename(temporary.path_.c_str(), path.c_str()) != 0) {
    fail(path, std::string("cannot rename the temporary file: ") + std::strerror(errno));
  }
  temporary.path_.clear();
  // The rename is durable only once the folder itself is synced.
  const int folder_fd = ::open(folder.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (folder_fd < 0) fail(path, std::string("cannot open its folder: ") + std::strerror(errno));
  const int synced = ::fsync(folder_fd);
  const int sync_error = errno;
  ::close(folder_fd);
  // Some file systems cannot sync a folder; the rename is then as durable as they allow.
  if (synced != 0 && sync_error != EINVAL && sync_error != ENOTSUP) {
    fail(path, std::string("cannot fsync its folder: ") + std::strerror(sync_error));
  }
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
  write_file_atomically(path, document.dump(1) + "\n");
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
