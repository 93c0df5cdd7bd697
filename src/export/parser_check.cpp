#include "motoflex/export/parser_check.hpp"

#include <console_bridge/console.h>
#include <urdf_parser/urdf_parser.h>

#include <sdf/sdf_config.h>
#include <sdf/Root.hh>

#include "mujoco_model.hpp"

namespace motoflex {
namespace {

// Collects console_bridge messages (urdfdom reports its errors only through them).
class CapturingOutputHandler final : public console_bridge::OutputHandler {
 public:
  void log(const std::string& text, console_bridge::LogLevel level, const char*, int) override {
    if (level >= console_bridge::CONSOLE_BRIDGE_LOG_WARN) {
      if (!messages.empty()) messages += "; ";
      messages += text;
    }
  }
  std::string messages;
};

}  // namespace

std::string urdfdom_errors(const std::string& urdf_text) {
  CapturingOutputHandler handler;
  console_bridge::useOutputHandler(&handler);
  const urdf::ModelInterfaceSharedPtr model = urdf::parseURDF(urdf_text);
  console_bridge::restorePreviousOutputHandler();
  if (model) return "";
  return handler.messages.empty() ? "urdfdom rejected the URDF" : handler.messages;
}

std::string sdformat_errors(const std::string& sdf_text) {
  sdf::Root root;
  const sdf::Errors errors = root.LoadSdfString(sdf_text);
  std::string out;
  for (const sdf::Error& error : errors) {
    if (!out.empty()) out += "; ";
    out += error.Message();
  }
  return out;
}

std::string mujoco_errors(const std::string& mjcf_text, const std::vector<ExportedAsset>& assets) {
  std::string error;
  const detail::MjModelPtr model = detail::load_mjcf_text(mjcf_text, assets, error);
  if (!model && error.empty()) return "MuJoCo rejected the model";
  return error;
}

std::string parser_name(const std::string& format) {
  if (format == "urdf") return "urdfdom (urdf::parseURDF)";
  if (format == "sdf") return std::string("sdformat ") + SDF_VERSION_FULL;
  if (format == "mjcf") return std::string("MuJoCo ") + mj_versionString();
  return "";
}

}  // namespace motoflex
