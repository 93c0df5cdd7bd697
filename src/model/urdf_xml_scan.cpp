#include "urdf_xml_scan.hpp"

#include <tinyxml.h>

#include <fstream>
#include <sstream>

#include "motoflex/core/error.hpp"

namespace motoflex::detail {
namespace {

const char* name_of(const TiXmlElement& element) {
  const char* name = element.Attribute("name");
  return name == nullptr ? "" : name;
}

// Renames the <capsule> of each <collision>/<visual> `tag` of a link; returns whether any was.
bool rename_capsules(TiXmlElement& link, const char* tag,
                     std::set<std::pair<std::string, int>>& out) {
  bool renamed = false;
  int index = 0;
  for (TiXmlElement* shape = link.FirstChildElement(tag); shape != nullptr;
       shape = shape->NextSiblingElement(tag), ++index) {
    TiXmlElement* geometry = shape->FirstChildElement("geometry");
    TiXmlElement* capsule = geometry == nullptr ? nullptr : geometry->FirstChildElement("capsule");
    if (capsule == nullptr) continue;
    capsule->SetValue("cylinder");
    out.emplace(name_of(link), index);
    renamed = true;
  }
  return renamed;
}

}  // namespace

UrdfXmlScan scan_urdf_xml(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw InputError(path, 0, "", "cannot open URDF file");
  std::stringstream buffer;
  buffer << file.rdbuf();
  UrdfXmlScan scan;
  scan.text = buffer.str();

  TiXmlDocument document;
  document.Parse(scan.text.c_str(), nullptr, TIXML_ENCODING_UTF8);
  if (document.Error()) {
    throw InputError(path, document.ErrorRow(), "",
                     std::string("not well-formed XML: ") + document.ErrorDesc());
  }
  TiXmlElement* robot = document.RootElement();
  if (robot == nullptr || std::string(robot->Value()) != "robot") {
    throw InputError(path, robot == nullptr ? 0 : robot->Row(), "",
                     "the root element must be <robot>");
  }
  bool renamed = false;
  for (TiXmlElement* element = robot->FirstChildElement(); element != nullptr;
       element = element->NextSiblingElement()) {
    const std::string tag = element->Value();
    if (tag == "link") {
      scan.link_lines.emplace(name_of(*element), element->Row());
      renamed = rename_capsules(*element, "collision", scan.capsule_collisions) || renamed;
      renamed = rename_capsules(*element, "visual", scan.capsule_visuals) || renamed;
    } else if (tag == "joint") {
      scan.joint_lines.emplace(name_of(*element), element->Row());
      scan.joint_order.emplace_back(name_of(*element));
    }
  }
  if (renamed) {
    TiXmlPrinter printer;
    document.Accept(&printer);
    scan.text = printer.CStr();
  }
  return scan;
}

}  // namespace motoflex::detail
