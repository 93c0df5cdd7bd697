#pragma once

// Internal to the exporters: a small XML element tree that prints itself with indentation, and
// number formatting that round-trips (the shortest decimal that reads back as the same double),
// so a value written into a URDF, SDF or MJCF file comes back bit-identical from its parser.

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace motoflex::detail {

// Shortest decimal form of `value` that parses back to the same double ("0.1", "1e-05").
std::string format_number(double value);
// Space-separated numbers: "x y z".
std::string format_numbers(const std::vector<double>& values);
std::string format_vector(const Eigen::Vector3d& v);
// MuJoCo order "w x y z".
std::string format_quaternion_wxyz(const Eigen::Matrix3d& rotation);
// SDF/URDF roll-pitch-yaw (fixed axes X, then Y, then Z).
std::string format_rpy(const Eigen::Matrix3d& rotation);
std::string xml_escape(std::string_view text);

class XmlElement {
 public:
  explicit XmlElement(std::string name) : name_(std::move(name)) {}

  XmlElement& attribute(const std::string& name, const std::string& value);
  XmlElement& attribute(const std::string& name, const char* value) {
    return attribute(name, std::string(value));
  }
  XmlElement& attribute(const std::string& name, double value) {
    return attribute(name, format_number(value));
  }
  // Appends a child element and returns it; the reference stays valid while more are added.
  XmlElement& child(const std::string& name);
  // Appends <name>text</name>.
  XmlElement& text_child(const std::string& name, const std::string& text);
  XmlElement& text_child(const std::string& name, double value) {
    return text_child(name, format_number(value));
  }
  // Appends <!-- text -->.
  void comment(const std::string& text);
  // Prints this element (and its children) indented by `depth` levels of two spaces.
  std::string to_string(int depth = 0) const;

 private:
  std::string name_;  // empty for a comment node
  std::string text_;
  std::vector<std::pair<std::string, std::string>> attributes_;
  std::vector<std::unique_ptr<XmlElement>> children_;
};

}  // namespace motoflex::detail
