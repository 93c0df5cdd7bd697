#include "motoflex/effects/loop_identity.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "motoflex/core/atomic_file.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/core/text_hash.hpp"

namespace motoflex {
namespace {

namespace fs = std::filesystem;

// The parts of the identity, each hashed, so a mismatch can say which part changed.
nlohmann::ordered_json identity_parts(const FitConfig& config) {
  const nlohmann::ordered_json spec = fit_spec_to_json(config);
  nlohmann::ordered_json parts;
  parts["format"] = 1;
  parts["base_fit"] = hash_text(fit_identity(config).dump());
  parts["budget"] = hash_text(spec["budget"].dump());
  parts["loop"] = hash_text(spec["loop"].dump());
  return parts;
}

std::string describe(const std::string& part) {
  if (part == "base_fit")
    return "the base fit (scenario, robot, logs, free parameters, fitness, strategy or seed)";
  if (part == "budget") return "the base fit's budget";
  if (part == "loop")
    return "the loop: section (candidates, iterations, refit strategy, budget, polish or scan)";
  return part;
}

}  // namespace

void check_loop_identity(const FitConfig& config, const std::string& out_dir) {
  const fs::path path = fs::path(out_dir) / "loop_identity.json";
  const nlohmann::ordered_json parts = identity_parts(config);
  if (!fs::exists(path)) {
    fs::create_directories(out_dir);
    write_file_atomically(path.string(), parts.dump(2) + "\n");
    return;
  }
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  nlohmann::json stored;
  try {
    stored = nlohmann::json::parse(text.str());
  } catch (const nlohmann::json::exception& error) {
    throw InputError(
        path.string(), 0, "",
        std::string("corrupt: ") + error.what() + "; delete the folder to start the loop again");
  }
  std::vector<std::string> changed;
  for (const auto& [part, hash] : parts.items()) {
    if (!stored.contains(part) || stored[part] != hash) changed.push_back(describe(part));
  }
  if (changed.empty()) return;
  std::string message = "this folder holds a loop run with another config or data (changed: ";
  for (std::size_t i = 0; i < changed.size(); ++i) message += (i ? "; " : "") + changed[i];
  message += "): its refits would be reused as they are. Choose another --out, or delete " +
             out_dir + " to start again";
  throw InputError(path.string(), 0, "", message);
}

}  // namespace motoflex
