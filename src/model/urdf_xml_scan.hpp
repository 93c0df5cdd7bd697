#pragma once

// Internal to the URDF reader: one pass over the URDF's XML (tinyxml) for what urdfdom does
// not keep: the line of every link and joint, the joints' document order, and <capsule>
// shapes, which urdfdom rejects (and with them every other shape of the link).

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace motoflex::detail {

struct UrdfXmlScan {
  // The text for urdfdom: the file itself, or with every <capsule> renamed <cylinder> (same
  // attributes: radius, length) when it has capsules.
  std::string text;
  std::map<std::string, int> link_lines;   // link name → line of its <link>
  std::map<std::string, int> joint_lines;  // joint name → line of its <joint>
  std::vector<std::string> joint_order;    // joint names in document order
  // (link, index among the link's <collision>s / <visual>s) of each shape written <capsule>.
  std::set<std::pair<std::string, int>> capsule_collisions;
  std::set<std::pair<std::string, int>> capsule_visuals;
};

// Reads `path`. Throws InputError for a file that cannot be opened or is not well-formed XML
// with a <robot> root (with tinyxml's line).
UrdfXmlScan scan_urdf_xml(const std::string& path);

}  // namespace motoflex::detail
