#pragma once

// Small robots of our own for the tests: URDF snippets and robot folders written into a fresh
// test folder. Meshes come from tests/data/meshes (scripts/make_meshes.py --tests).

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace motoflex::testing {

inline std::string mesh_path(const std::string& file) {
  return std::string(MOTOFLEX_SOURCE_DIR) + "/tests/data/meshes/" + file;
}

inline std::string num(double value) {
  std::ostringstream out;
  out.precision(17);
  out << value;
  return out.str();
}

// <inertial> of a solid box of mass m and edges x, y, z at the link origin (or `com`).
inline std::string box_inertial(double mass_kg, double x, double y, double z,
                                const std::string& com = "0 0 0") {
  const double ixx = mass_kg * (y * y + z * z) / 12.0;
  const double iyy = mass_kg * (x * x + z * z) / 12.0;
  const double izz = mass_kg * (x * x + y * y) / 12.0;
  return "<inertial><origin xyz=\"" + com + "\"/><mass value=\"" + num(mass_kg) +
         "\"/><inertia ixx=\"" + num(ixx) + "\" ixy=\"0\" ixz=\"0\" iyy=\"" + num(iyy) +
         "\" iyz=\"0\" izz=\"" + num(izz) + "\"/></inertial>";
}

inline std::string collision(const std::string& geometry, const std::string& origin = "") {
  return "<collision>" + (origin.empty() ? "" : "<origin " + origin + "/>") + "<geometry>" +
         geometry + "</geometry></collision>";
}

inline std::string link(const std::string& name, const std::string& body) {
  return "<link name=\"" + name + "\">" + body + "</link>\n";
}

inline std::string joint(const std::string& name, const std::string& type,
                         const std::string& parent, const std::string& child,
                         const std::string& extra = "") {
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent +
         "\"/><child link=\"" + child + "\"/>" + extra + "</joint>\n";
}

inline std::string robot(const std::string& name, const std::string& body) {
  return "<?xml version=\"1.0\"?>\n<robot name=\"" + name + "\">\n" + body + "</robot>\n";
}

inline void write_file(const std::filesystem::path& path, const std::string& text) {
  std::filesystem::create_directories(path.parent_path());
  std::ofstream(path) << text;
}

// The parameters a robot needs with the ideal servo (the force limit only with sliders), as
// robot.yaml lines.
inline std::string ideal_parameters(bool sliders = false) {
  return std::string("parameters:\n  ideal.torque_max_nm: [100.0, 1.0, 1000.0]\n") +
         (sliders ? "  ideal.force_max_n: [1000.0, 1.0, 10000.0]\n" : "") +
         "  contact.mu: [1.0, 0.1, 2.0]\n"
         "  contact.soft_erp: [0.2, 0.05, 0.9]\n"
         "  contact.soft_cfm: [1.0e-4, 1.0e-7, 1.0e-2]\n"
         "  contact.slip: [1.0e-3, 1.0e-5, 0.05]\n"
         "  world.erp: [0.2, 0.05, 0.9]\n"
         "  world.cfm: [1.0e-10, 1.0e-12, 1.0e-4]\n";
}

}  // namespace motoflex::testing
