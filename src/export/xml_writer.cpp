#include "xml_writer.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <stdexcept>

#include "motoflex/core/markup_escape.hpp"

namespace motoflex::detail {

std::string format_number(double value) {
  if (!std::isfinite(value)) throw std::invalid_argument("cannot export a non-finite number");
  if (value == 0.0) return "0";  // also turns −0 into 0
  char buffer[32];
  const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
  return std::string(buffer, result.ptr);
}

std::string format_numbers(const std::vector<double>& values) {
  std::string out;
  for (const double v : values) {
    if (!out.empty()) out += ' ';
    out += format_number(v);
  }
  return out;
}

std::string format_vector(const Eigen::Vector3d& v) {
  return format_numbers({v.x(), v.y(), v.z()});
}

std::string format_quaternion_wxyz(const Eigen::Matrix3d& rotation) {
  const Eigen::Quaterniond q(rotation);
  return format_numbers({q.w(), q.x(), q.y(), q.z()});
}

std::string format_rpy(const Eigen::Matrix3d& R) {
  // R = Rz(yaw)·Ry(pitch)·Rx(roll)
  const double pitch = std::asin(std::clamp(-R(2, 0), -1.0, 1.0));
  double roll = 0.0, yaw = 0.0;
  if (std::abs(R(2, 0)) < 1.0 - 1e-12) {
    roll = std::atan2(R(2, 1), R(2, 2));
    yaw = std::atan2(R(1, 0), R(0, 0));
  } else {
    yaw = std::atan2(-R(0, 1), R(1, 1));  // gimbal lock: put everything into yaw
  }
  return format_numbers({roll, pitch, yaw});
}

std::string xml_escape(std::string_view text) {
  return escape_markup(text);
}

XmlElement& XmlElement::attribute(const std::string& name, const std::string& value) {
  for (auto& [key, existing] : attributes_) {
    if (key == name) {
      existing = value;
      return *this;
    }
  }
  attributes_.emplace_back(name, value);
  return *this;
}

XmlElement& XmlElement::child(const std::string& name) {
  children_.push_back(std::make_unique<XmlElement>(name));
  return *children_.back();
}

XmlElement& XmlElement::text_child(const std::string& name, const std::string& text) {
  XmlElement& element = child(name);
  element.text_ = text;
  return element;
}

void XmlElement::comment(const std::string& text) {
  auto node = std::make_unique<XmlElement>("");
  // "--" may not appear inside an XML comment.
  std::string safe = text;
  for (std::size_t at = safe.find("--"); at != std::string::npos; at = safe.find("--", at)) {
    safe.replace(at, 2, "- -");
  }
  node->text_ = safe;
  children_.push_back(std::move(node));
}

std::string XmlElement::to_string(int depth) const {
  const std::string indent(2 * depth, ' ');
  if (name_.empty()) return indent + "<!-- " + text_ + " -->\n";
  std::string out = indent + "<" + name_;
  for (const auto& [key, value] : attributes_) out += " " + key + "=\"" + xml_escape(value) + "\"";
  if (children_.empty() && text_.empty()) return out + "/>\n";
  if (children_.empty()) return out + ">" + xml_escape(text_) + "</" + name_ + ">\n";
  out += ">\n";
  for (const auto& c : children_) out += c->to_string(depth + 1);
  return out + indent + "</" + name_ + ">\n";
}

}  // namespace motoflex::detail
