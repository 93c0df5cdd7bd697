#include "motoflex/effects/loop_identity.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vector>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/folder_lock.hpp"
#include "motoflex/core/text_hash.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

constexpr const char* kPrevious = "previous-";

// The parts of the identity, each hashed, so a mismatch can say which part changed.
nlohmann::json identity_parts(const FitConfig& config) {
  const nlohmann::ordered_json spec = fit_spec_to_json(config);
  nlohmann::json parts;
  parts["format"] = 1;
  parts["base_fit"] = config.hash;  // FitConfig::identity, hashed when the config was loaded
  parts["budget"] = hash_text(spec["budget"].dump());
  parts["loop"] = hash_text(spec["loop"].dump());
  return parts;
}

std::string describe(const std::string& part) {
  if (part == "base_fit") {
    return "the base fit: scenario, robot, logs, free parameters, fitness, strategy or seed";
  }
  if (part == "budget") return "the base fit's budget";
  if (part == "loop") return "the loop: section: candidates, iterations, refit settings";
  return part;
}

// What changed between the stored identity and this one ("" = nothing).
std::string changes(const fs::path& path, const nlohmann::json& parts) {
  std::ifstream in(path);
  const nlohmann::json stored = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
  if (!stored.is_object()) return "its loop_identity.json is unreadable";
  std::string out;
  for (const auto& [part, hash] : parts.items()) {
    if (stored.contains(part) && stored[part] == hash) continue;
    out += (out.empty() ? "" : "; ") + describe(part);
  }
  return out;
}

// Moves everything in `out` but the lock and earlier previous-N folders into the first free
// previous-N folder, which it returns.
fs::path move_aside(const fs::path& out) {
  fs::path aside;
  for (int k = 1;; ++k) {
    aside = out / (kPrevious + std::to_string(k));
    if (!fs::exists(aside)) break;
  }
  std::vector<fs::path> entries;
  for (const auto& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    if (name == FolderLock::kFileName || name.rfind(kPrevious, 0) == 0) continue;
    entries.push_back(entry.path());
  }
  fs::create_directories(aside);
  for (const fs::path& entry : entries) fs::rename(entry, aside / entry.filename());
  return aside;
}

}  // namespace

std::string check_loop_identity(const FitConfig& config, const std::string& out_dir) {
  const fs::path out(out_dir);
  const fs::path path = out / "loop_identity.json";
  const nlohmann::json parts = identity_parts(config);
  std::string notice;
  if (fs::exists(path)) {
    const std::string changed = changes(path, parts);
    if (changed.empty()) return "";
    try {
      const fs::path aside = move_aside(out);
      notice = out_dir + " held a loop of another config or data (changed: " + changed +
               "); its files are now in " + aside.string() + ", and the loop starts afresh";
    } catch (const fs::filesystem_error& error) {
      throw InputError(path.string(), 0, "",
                       "this folder holds a loop of another config or data (changed: " + changed +
                           ") and moving it aside failed (" + error.what() +
                           "); choose another --out");
    }
  }
  fs::create_directories(out);
  write_file_atomically(path.string(), parts.dump(2) + "\n");
  return notice;
}

}  // namespace motoflex
