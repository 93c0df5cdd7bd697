#include "motoflex/export/mjcf_export.hpp"

#include <algorithm>
#include <cmath>

#include "exported_bodies.hpp"
#include "exported_shapes.hpp"
#include "exported_visuals.hpp"
#include "motoflex/core/build_info.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/export/exported_file.hpp"
#include "xml_writer.hpp"

namespace motoflex {
namespace {

using detail::ExportedBody;
using detail::format_number;
using detail::format_numbers;
using detail::format_vector;
using detail::XmlElement;

constexpr int kContactPointsPerFoot = 4;  // motoflex collides each foot box in up to 4 points
// Impedance close to 1: the contact follows the solref spring-damper (ODE's soft contact has no
// position-dependent impedance).
constexpr const char* kContactSolimp = "0.99 0.99 0.001";

struct Writer {
  const ExportInput& input;
  const MjcfOptions& options;
  std::vector<ActuatorExport> actuators;
  FlexExport flex;
  std::vector<ExportedBody> bodies;
  std::vector<std::vector<VisualShape>> visuals;       // body → what a viewer draws
  std::vector<std::vector<int>> children;              // body → child bodies
  Eigen::Vector3d offset_m = Eigen::Vector3d::Zero();  // placement of the whole robot
  std::string contact_solref;                          // of the feet and the floor

  void add_joint(XmlElement& body, const std::string& name, const Eigen::Vector3d& pos,
                 const Eigen::Vector3d& axis, int actuator) const {
    XmlElement& joint = body.child("joint");
    const bool slide = actuator >= 0 && input.model.actuators[actuator].prismatic;
    joint.attribute("name", name).attribute("type", slide ? "slide" : "hinge");
    joint.attribute("pos", format_vector(pos)).attribute("axis", format_vector(axis));
    if (actuator < 0) {
      joint.attribute("limited", "false");
      return;
    }
    const ActuatorExport& a = actuators[actuator];
    // qpos is what the encoder reads, θ + m: the written pose is qpos = m, and the stops (on θ)
    // move with it.
    const double m = a.mounting_offset_rad;
    if (m != 0.0) joint.attribute("ref", m);
    if (a.limited) {
      joint.attribute("limited", "true")
          .attribute("range", format_numbers({a.lower_rad + m, a.upper_rad + m}));
    } else {
      joint.attribute("limited", "false");
    }
    joint.attribute("damping", a.damping_nm_s_per_rad).attribute("frictionloss", a.friction_nm);
    joint.attribute("armature", options.armature ? a.armature : 0.0);
  }

  void add_flex_joint(XmlElement& body, const std::string& name, const Eigen::Vector3d& pos,
                      const Eigen::Vector3d& axis) const {
    XmlElement& joint = body.child("joint");
    joint.attribute("name", name).attribute("type", "hinge").attribute("limited", "false");
    joint.attribute("pos", format_vector(pos)).attribute("axis", format_vector(axis));
    joint.attribute("stiffness", flex.spring_nm_per_rad)
        .attribute("damping", flex.damping_nm_s_per_rad)
        .attribute("frictionloss", flex.friction_nm);
  }

  // Visual geoms: drawn (group 1, shown by default), never colliding, no mass (the compiler
  // takes inertias from <inertial> only, inertiafromgeom="false"; mass 0 says so again).
  void add_visual_geoms(XmlElement& element, int b) const {
    const std::string& body = bodies[b].spec->name;
    for (std::size_t k = 0; k < visuals[b].size(); ++k) {
      const VisualShape& shape = visuals[b][k];
      XmlElement& geom = element.child("geom");
      const std::string name = detail::visual_geom_name(body, shape, k);
      geom.attribute("name", name);
      detail::set_mjcf_geom(geom, shape, "mesh_" + name);
      geom.attribute("pos", format_vector(shape.X_BG.translation()));
      geom.attribute("quat", detail::format_quaternion_wxyz(shape.X_BG.linear()));
      geom.attribute("contype", "0").attribute("conaffinity", "0").attribute("group", "1");
      geom.attribute("mass", "0").attribute("rgba", detail::visual_rgba(shape));
    }
  }

  // Collision geoms in group 3 (hidden by MuJoCo's viewer by default; the visuals show them).
  void add_geoms(XmlElement& element, const ExportedBody& body) const {
    for (std::size_t k = 0; k < body.spec->collisions.size(); ++k) {
      const CollisionShape& shape = body.spec->collisions[k];
      XmlElement& geom = element.child("geom");
      const std::string name = detail::shape_geom_name(shape, k);
      geom.attribute("name", name);
      detail::set_mjcf_geom(geom, shape, "mesh_" + name);
      const Eigen::Isometry3d pose = detail::exported_shape_pose(body, shape.X_BG, offset_m);
      geom.attribute("pos", format_vector(pose.translation()));
      geom.attribute("quat", detail::format_quaternion_wxyz(pose.linear()));
      geom.attribute("group", "3").attribute("rgba", "0.9 0.45 0.2 0.5");
      // Only feet and contact links touch the ground (floor: contype 0, conaffinity 1);
      // nothing else collides.
      const bool touches = shape.contact != GroundContact::kFall;
      geom.attribute("contype", touches ? "1" : "0").attribute("conaffinity", "0");
      if (touches) {
        // MuJoCo mixes the two geoms' contact parameters: give both the same.
        geom.attribute("friction", format_numbers({input.parameters.get("contact.mu"), 0.0, 0.0}))
            .attribute("solref", contact_solref)
            .attribute("solimp", kContactSolimp);
      }
    }
  }

  void add_body(XmlElement& parent, int b, const Eigen::Vector3d& parent_com) const {
    const RobotModel& model = input.model;
    const ExportedBody& body = bodies[b];
    XmlElement& element = parent.child("body");
    element.attribute("name", body.spec->name);
    element.attribute("pos", format_vector(body.com_m - parent_com));
    if (body.spec->links.size() > 1) {
      std::string links;
      for (const auto& l : body.spec->links) links += (links.empty() ? "" : ", ") + l;
      element.comment("URDF links welded into this body: " + links);
    }
    if (b == model.root_body && !model.fixed_base && !options.weld_root) {
      element.child("joint").attribute("name", "root").attribute("type", "free");
    }
    if (body.spec->parent_joint >= 0) {
      const JointSpec& joint = model.joints[body.spec->parent_joint];
      // Joint positions are relative to this body's frame (at its CoM).
      const Eigen::Vector3d pos = joint.anchor_W0_m + offset_m - body.com_m;
      if (joint.kind == JointKind::kFlex) {
        add_flex_joint(element, joint.name + "_1", pos, joint.axis1_W0);
        add_flex_joint(element, joint.name + "_2", pos, joint.axis2_W0);
      } else {
        add_joint(element, actuator_or(joint.actuator1, joint.name), pos, joint.axis1_W0,
                  joint.actuator1);
        if (joint.kind == JointKind::kUniversal) {
          add_joint(element, actuator_or(joint.actuator2, joint.name + "_2"), pos, joint.axis2_W0,
                    joint.actuator2);
        }
      }
    }
    const Eigen::Matrix3d& I = body.inertia_kg_m2;
    element.child("inertial")
        .attribute("pos", "0 0 0")
        .attribute("mass", body.mass_kg)
        .attribute("fullinertia",
                   format_numbers({I(0, 0), I(1, 1), I(2, 2), I(0, 1), I(0, 2), I(1, 2)}));
    add_geoms(element, body);
    add_visual_geoms(element, b);
    for (const int c : children[b]) add_body(element, c, body.com_m);
  }

  std::string actuator_or(int actuator, const std::string& fallback) const {
    return actuator >= 0 ? actuators[actuator].joint : fallback;
  }
};

// MuJoCo solref (timeconst, dampratio) of motoflex's ODE soft contact (see mjcf_export.hpp).
std::pair<double, double> contact_solref(const ExportInput& input, std::size_t foot_boxes) {
  const double h = input.dt_s;
  const double erp = input.parameters.get("contact.soft_erp");
  const double cfm = input.parameters.get("contact.soft_cfm");
  const double k = erp / (h * cfm);
  const double c = (1.0 - erp) / cfm;
  double mass = 0.0;
  for (const auto& body : input.model.bodies) mass += body.mass_kg;
  const double m =
      mass / static_cast<double>(kContactPointsPerFoot * std::max<std::size_t>(foot_boxes, 1));
  const double timeconst = std::max(2.0 * m / c, 2.0 * h);
  const double dampratio = c / (2.0 * std::sqrt(k * m));
  return {timeconst, dampratio};
}

// Mesh collisions as inline assets (MuJoCo collides their convex hulls, as motoflex does); mesh
// visuals as the exported mesh files next to the MJCF file.
void add_mesh_assets(XmlElement& mujoco, const Writer& w) {
  const RobotModel& model = w.input.model;
  XmlElement* asset = nullptr;
  auto assets = [&]() -> XmlElement& {
    if (asset == nullptr) asset = &mujoco.child("asset");
    return *asset;
  };
  for (const auto& body : model.bodies) {
    for (std::size_t k = 0; k < body.collisions.size(); ++k) {
      const CollisionShape& shape = body.collisions[k];
      if (shape.kind != ShapeKind::kMesh) continue;
      detail::add_mjcf_mesh_asset(assets(), shape, "mesh_" + detail::shape_geom_name(shape, k));
    }
  }
  for (std::size_t b = 0; b < w.visuals.size(); ++b) {
    for (std::size_t k = 0; k < w.visuals[b].size(); ++k) {
      const VisualShape& shape = w.visuals[b][k];
      if (shape.kind != ShapeKind::kMesh) continue;
      detail::add_mjcf_visual_mesh_asset(
          assets(), shape, mesh_asset_file(model, shape.mesh.path),
          "mesh_" + detail::visual_geom_name(w.bodies[b].spec->name, shape, k));
    }
  }
}

// The floor plane with the soft-contact solref, when some shape touches the ground.
void add_floor(XmlElement& world, Writer& w) {
  const ExportInput& input = w.input;
  std::size_t foot_boxes = 0;
  for (const auto& body : input.model.bodies) {
    for (const auto& shape : body.collisions) {
      foot_boxes += shape.contact != GroundContact::kFall ? 1 : 0;
    }
  }
  if (foot_boxes == 0) return;
  const auto [timeconst, dampratio] = contact_solref(input, foot_boxes);
  w.contact_solref = format_numbers({timeconst, dampratio});
  world.child("geom")
      .attribute("name", "floor")
      .attribute("type", "plane")
      .attribute("size", "0 0 1")
      .attribute("contype", "0")
      .attribute("conaffinity", "1")
      .attribute("friction", format_numbers({input.parameters.get("contact.mu"), 0.0, 0.0}))
      .attribute("solref", w.contact_solref)
      .attribute("solimp", kContactSolimp);
}

// URDF <mimic>: the follower's position is multiplier·leader + offset.
void add_mimic_equalities(XmlElement& mujoco, const Writer& w) {
  const RobotModel& model = w.input.model;
  bool has_mimic = false;
  for (const JointSpec& joint : model.joints) has_mimic |= joint.mimic.has_value();
  if (!has_mimic) return;
  XmlElement& equality = mujoco.child("equality");
  for (const JointSpec& joint : model.joints) {
    if (!joint.mimic) continue;
    const JointSpec& leader = model.joints[joint.mimic->leader_joint];
    const int leader_actuator = joint.mimic->leader_axis == 1 ? leader.actuator1 : leader.actuator2;
    equality.child("joint")
        .attribute("joint1", joint.name)
        .attribute("joint2",
                   w.actuator_or(leader_actuator,
                                 joint.mimic->leader_axis == 1 ? leader.name : leader.name + "_2"))
        .attribute("polycoef",
                   format_numbers({joint.mimic->offset, joint.mimic->multiplier, 0.0, 0.0, 0.0}));
  }
}

// One position actuator per servo (a PD with the servo's equivalent gains and torque limit).
void add_actuators(XmlElement& mujoco, const Writer& w) {
  XmlElement& actuator = mujoco.child("actuator");
  bool next_angle = false;
  for (const ActuatorExport& a : w.actuators) {
    next_angle = next_angle || a.command_is_next_angle;
    actuator.child("general")
        .attribute("name", a.joint)
        .attribute("joint", a.joint)
        .attribute("gainprm", a.kp_nm_per_rad)
        .attribute("biastype", "affine")
        .attribute("biasprm", format_numbers({0.0, -a.kp_nm_per_rad, -a.kv_nm_s_per_rad}))
        .attribute("forcelimited", "true")
        .attribute("forcerange", format_numbers({-a.effort_nm, a.effort_nm}));
  }
  if (next_angle) {
    actuator.comment(
        "ideal servo: set ctrl to the angle the joint must reach at the END of the "
        "step (motoflex's ideal servo closes the error in one step)");
  }
}

// Every motoflex parameter as a custom numeric, and the fit's provenance as a custom text.
void add_custom_data(XmlElement& mujoco, const ExportInput& input) {
  XmlElement& custom = mujoco.child("custom");
  const ParameterRegistry& registry = input.parameters.registry();
  for (std::size_t i = 0; i < registry.size(); ++i) {
    custom.child("numeric")
        .attribute("name", "motoflex:" + registry.spec(i).name)
        .attribute("data", input.parameters.get(i));
  }
  const FitProvenance& p = input.provenance;
  std::string provenance = "servo=" + input.servo;
  if (!p.source_path.empty()) provenance += " source=" + p.source_path;
  if (p.fitness) provenance += " fitness=" + format_number(*p.fitness);
  if (!p.config_hash.empty()) provenance += " config_hash=" + p.config_hash;
  if (!p.date.empty()) provenance += " date=" + p.date;
  if (!p.motoflex_version.empty()) provenance += " fit_motoflex_version=" + p.motoflex_version;
  provenance += " exported_by=motoflex_" + std::string(version());
  custom.child("text").attribute("name", "motoflex:provenance").attribute("data", provenance);
}

}  // namespace

std::string export_mjcf(const ExportInput& input, const MjcfOptions& options) {
  const RobotModel& model = input.model;
  Writer w{input, options, export_actuators(input), export_flex(input), {}, {}, {}, {}, {}};
  std::vector<double> pose = options.placement_pose_rad;
  if (pose.empty()) pose.assign(model.actuators.size(), 0.0);
  w.offset_m = detail::placement_offset_m(
      model, pose, options.clearance_m >= 0.0 ? options.clearance_m : model.initial_clearance_m);
  w.bodies = detail::exported_bodies(input, w.offset_m, false);
  w.children.resize(model.bodies.size());
  for (std::size_t b = 0; b < model.bodies.size(); ++b) {
    const int joint = model.bodies[b].parent_joint;
    if (joint >= 0) w.children[model.joints[joint].parent_body].push_back(static_cast<int>(b));
  }

  XmlElement mujoco("mujoco");
  mujoco.attribute("model", model.name);
  mujoco.comment(detail::export_header(input, " for MuJoCo 2.2.2+") +
                 ". Lost in MJCF: backlash, gear spring and mass, PID integral, motor "
                 "inductance, Stribeck/load friction, contact slip, sensor effects (see the JSON "
                 "export).");
  mujoco.comment(provenance_comment(input.provenance, input.servo));
  mujoco.child("compiler").attribute("angle", "radian").attribute("inertiafromgeom", "false");
  mujoco.child("option")
      .attribute("timestep", input.dt_s)
      .attribute("gravity", "0 0 -9.81")
      .attribute("integrator", "implicit")
      .attribute("cone", "pyramidal");

  for (const ExportedBody& body : w.bodies) {
    w.visuals.push_back(detail::exported_visuals(model, body, w.offset_m));
  }
  add_mesh_assets(mujoco, w);
  XmlElement& world = mujoco.child("worldbody");
  add_floor(world, w);
  w.add_body(world, model.root_body, Eigen::Vector3d::Zero());
  add_mimic_equalities(mujoco, w);
  add_actuators(mujoco, w);
  add_custom_data(mujoco, input);
  return mujoco.to_string();
}

}  // namespace motoflex
