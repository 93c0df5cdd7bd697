#pragma once

#include <string>
#include <vector>

#include "motoflex/export/exported_file.hpp"

namespace motoflex {

// Each exported text read back by its format's own parser, as installed on Debian 12. Every
// function returns what the parser complained about, or an empty string when it accepted the
// text without an error. Not thread-safe (urdfdom's and MuJoCo's error channels are global).

// urdfdom 3 (urdf::parseURDF); its console_bridge messages are captured while it parses.
std::string urdfdom_errors(const std::string& urdf_text);
// libsdformat 12 (sdf::Root::LoadSdfString): every sdf::Error.
std::string sdformat_errors(const std::string& sdf_text);
// MuJoCo (mj_loadXML from an in-memory file): the error buffer, plus any compiler warning.
// `assets` are the mesh files the text refers to, given to MuJoCo's virtual file system.
std::string mujoco_errors(const std::string& mjcf_text,
                          const std::vector<ExportedAsset>& assets = {});

// The parser and its version, for reports ("urdfdom 3.0", "sdformat 12.3.0", "MuJoCo 2.2.2").
std::string parser_name(const std::string& format);

}  // namespace motoflex
