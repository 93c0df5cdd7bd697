#include "motoflex/export/urdf_export.hpp"

#include <tinyxml.h>

#include <map>

#include "motoflex/core/build_info.hpp"
#include "motoflex/core/error.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "xml_writer.hpp"

namespace motoflex {
namespace {

using detail::format_number;

TiXmlElement* find_child(TiXmlElement* parent, const char* name, const std::string& name_attr) {
  for (TiXmlElement* e = parent->FirstChildElement(name); e != nullptr;
       e = e->NextSiblingElement(name)) {
    const char* attr = e->Attribute("name");
    if (attr != nullptr && name_attr == attr) return e;
  }
  return nullptr;
}

TiXmlElement* child_or_new(TiXmlElement* parent, const char* name) {
  if (TiXmlElement* e = parent->FirstChildElement(name)) return e;
  return parent->InsertEndChild(TiXmlElement(name))->ToElement();
}

TiXmlElement* add_text_element(TiXmlElement* parent, const char* name, const std::string& text) {
  TiXmlElement* e = parent->InsertEndChild(TiXmlElement(name))->ToElement();
  e->InsertEndChild(TiXmlText(text.c_str()));
  return e;
}

void set(TiXmlElement* e, const char* name, double value) {
  e->SetAttribute(name, format_number(value).c_str());
}

// Removes the file's own <transmission> elements of the actuated joints (URDFs from ROS
// packages often carry them), so that each joint has exactly the one add_transmission writes.
void remove_transmissions(TiXmlElement* robot, const std::vector<ActuatorExport>& actuators) {
  TiXmlElement* element = robot->FirstChildElement("transmission");
  while (element != nullptr) {
    TiXmlElement* next = element->NextSiblingElement("transmission");
    bool actuated = false;
    for (TiXmlElement* joint = element->FirstChildElement("joint"); joint != nullptr;
         joint = joint->NextSiblingElement("joint")) {
      const char* name = joint->Attribute("name");
      for (const ActuatorExport& a : actuators) actuated = actuated || (name && a.joint == name);
    }
    if (actuated) robot->RemoveChild(element);
    element = next;
  }
}

void add_transmission(TiXmlElement* robot, const ActuatorExport& a) {
  TiXmlElement transmission("transmission");
  transmission.SetAttribute("name", (a.joint + "_transmission").c_str());
  add_text_element(&transmission, "type", "transmission_interface/SimpleTransmission");
  TiXmlElement* joint = transmission.InsertEndChild(TiXmlElement("joint"))->ToElement();
  joint->SetAttribute("name", a.joint.c_str());
  add_text_element(joint, "hardwareInterface", "hardware_interface/PositionJointInterface");
  TiXmlElement* actuator = transmission.InsertEndChild(TiXmlElement("actuator"))->ToElement();
  actuator->SetAttribute("name", (a.joint + "_motor").c_str());
  add_text_element(actuator, "mechanicalReduction", format_number(a.reduction));
  robot->InsertEndChild(transmission);
}

void add_provenance(TiXmlElement* parent, const FitProvenance& p) {
  TiXmlElement* e = parent->InsertEndChild(TiXmlElement("motoflex:provenance"))->ToElement();
  const std::map<std::string, std::string> fields = {{"source", p.source_path},
                                                     {"fit", p.fit_config},
                                                     {"config_hash", p.config_hash},
                                                     {"date", p.date},
                                                     {"motoflex_version", p.motoflex_version}};
  if (p.fitness) set(e, "fitness", *p.fitness);
  for (const auto& [key, value] : fields) {
    if (!value.empty()) e->SetAttribute(key.c_str(), value.c_str());
  }
  e->SetAttribute("exported_at", utc_now_iso8601().c_str());
  e->SetAttribute("exported_by", (std::string("motoflex ") + version()).c_str());
}

void add_model_extension(TiXmlElement* robot, const ExportInput& input,
                         const std::vector<ActuatorExport>& actuators) {
  TiXmlElement* model = robot->InsertEndChild(TiXmlElement("motoflex:model"))->ToElement();
  model->SetAttribute("robot", input.model.name.c_str());
  model->SetAttribute("servo", input.servo);
  model->SetAttribute("format_version", "1");
  add_provenance(model, input.provenance);
  for (const ActuatorExport& a : actuators) {
    TiXmlElement* joint = model->InsertEndChild(TiXmlElement("motoflex:joint"))->ToElement();
    joint->SetAttribute("name", a.joint.c_str());
    joint->SetAttribute("group", a.group.c_str());
    set(joint, "servo_kp_nm_per_rad", a.kp_nm_per_rad);
    set(joint, "servo_kv_nm_s_per_rad", a.kv_nm_s_per_rad);
    set(joint, a.prismatic ? "armature_kg" : "armature_kg_m2", a.armature);
  }
  const ParameterRegistry& registry = input.parameters.registry();
  for (std::size_t i = 0; i < registry.size(); ++i) {
    TiXmlElement* p = model->InsertEndChild(TiXmlElement("motoflex:parameter"))->ToElement();
    p->SetAttribute("name", registry.spec(i).name.c_str());
    set(p, "value", input.parameters.get(i));
    p->SetAttribute("unit", registry.spec(i).unit.c_str());
  }
}

}  // namespace

std::string export_urdf(const ExportInput& input) {
  const std::string& path = input.model.urdf_path;
  TiXmlDocument document;
  if (!document.LoadFile(path.c_str())) {
    throw InputError(path, document.ErrorRow(), "", document.ErrorDesc());
  }
  TiXmlElement* robot = document.FirstChildElement("robot");
  if (robot == nullptr) throw InputError(path, 0, "robot", "no <robot> element");
  robot->SetAttribute("xmlns:motoflex", kMotoflexXmlNamespace);

  const std::vector<ActuatorExport> actuators = export_actuators(input);
  for (const ActuatorExport& a : actuators) {
    TiXmlElement* joint = find_child(robot, "joint", a.joint);
    if (joint == nullptr) throw InputError(path, 0, a.joint, "joint not found in the URDF");
    TiXmlElement* limit = child_or_new(joint, "limit");
    set(limit, "effort", a.effort_nm);
    if (a.velocity_rad_s > 0.0 || limit->Attribute("velocity") == nullptr) {
      set(limit, "velocity", a.velocity_rad_s);
    }
    TiXmlElement* dynamics = child_or_new(joint, "dynamics");
    set(dynamics, "damping", a.damping_nm_s_per_rad);
    set(dynamics, "friction", a.friction_nm);
  }
  const std::string note =
      " Exported by motoflex " + std::string(version()) + " (servo " + input.servo +
      "): fitted <dynamics> and <limit effort velocity> on the actuated joints, one "
      "<transmission> each; <motoflex:model> at the end carries every fitted parameter that "
      "URDF has no element for. ";
  TiXmlNode* first = robot->InsertBeforeChild(robot->FirstChild(), TiXmlComment(note.c_str()));
  robot->InsertAfterChild(first,
                          TiXmlComment(provenance_comment(input.provenance, input.servo).c_str()));
  remove_transmissions(robot, actuators);
  for (const ActuatorExport& a : actuators) add_transmission(robot, a);
  add_model_extension(robot, input, actuators);

  TiXmlPrinter printer;
  printer.SetIndent("  ");
  document.Accept(&printer);
  return printer.CStr();
}

}  // namespace motoflex
