#include "motoflex/export/sdf_export.hpp"

#include <cmath>

#include "exported_bodies.hpp"
#include "exported_shapes.hpp"
#include "exported_visuals.hpp"
#include "motoflex/export/actuator_export.hpp"
#include "motoflex/export/exported_file.hpp"
#include "motoflex/export/servo_export.hpp"
#include "motoflex/export/urdf_export.hpp"
#include "xml_writer.hpp"

namespace motoflex {
namespace {

using detail::ExportedBody;
using detail::format_number;
using detail::format_vector;
using detail::XmlElement;

constexpr double kUnlimited_rad = 1e16;  // SDF's default for an unlimited axis

std::string pose_text(const Eigen::Vector3d& position, const Eigen::Matrix3d& rotation) {
  return format_vector(position) + " " + detail::format_rpy(rotation);
}

void add_surface(XmlElement& collision, const ParameterSet& p) {
  XmlElement& surface = collision.child("surface");
  XmlElement& friction = surface.child("friction").child("ode");
  friction.text_child("mu", p.get("contact.mu"));
  friction.text_child("mu2", p.get("contact.mu"));
  friction.text_child("slip1", p.get("contact.slip"));
  friction.text_child("slip2", p.get("contact.slip"));
  XmlElement& contact = surface.child("contact").child("ode");
  contact.text_child("soft_cfm", p.get("contact.soft_cfm"));
  contact.text_child("soft_erp", p.get("contact.soft_erp"));
  contact.text_child("min_depth", 0.0);
}

void add_physics(XmlElement& world, const ExportInput& input) {
  XmlElement& physics = world.child("physics");
  physics.attribute("name", "motoflex_ode").attribute("type", "ode").attribute("default", "true");
  physics.text_child("max_step_size", input.dt_s);
  physics.text_child("real_time_factor", 1.0);
  physics.text_child("real_time_update_rate", 0.0);  // as fast as possible
  XmlElement& ode = physics.child("ode");
  XmlElement& solver = ode.child("solver");
  solver.text_child("type", "world");  // dWorldStep, motoflex's default stepper
  XmlElement& constraints = ode.child("constraints");
  constraints.text_child("cfm", input.parameters.get("world.cfm"));
  constraints.text_child("erp", input.parameters.get("world.erp"));
  // motoflex leaves ODE's defaults: no limit on the contact correcting velocity, no layer.
  constraints.text_child("contact_max_correcting_vel", 1e6);
  constraints.text_child("contact_surface_layer", 0.0);
}

void add_ground(XmlElement& world, const ExportInput& input) {
  XmlElement& model = world.child("model");
  model.attribute("name", "ground_plane");
  model.text_child("static", "true");
  XmlElement& link = model.child("link");
  link.attribute("name", "ground");
  XmlElement& collision = link.child("collision");
  collision.attribute("name", "ground");
  XmlElement& plane = collision.child("geometry").child("plane");
  plane.text_child("normal", "0 0 1");
  plane.text_child("size", "100 100");
  add_surface(collision, input.parameters);
}

// The exported mesh file a mesh shape refers to ("" for primitives and unresolved meshes).
std::string mesh_uri(const RobotModel& robot, const ShapeGeometry& shape) {
  if (shape.kind != ShapeKind::kMesh || shape.mesh.path.empty()) return "";
  return mesh_asset_file(robot, shape.mesh.path);
}

void add_link(XmlElement& model, const ExportedBody& body, const ExportInput& input,
              const Eigen::Vector3d& offset_m) {
  XmlElement& link = model.child("link");
  link.attribute("name", body.spec->name);
  link.text_child("pose", pose_text(body.com_m, Eigen::Matrix3d::Identity()));
  if (body.spec->links.size() > 1) {
    std::string links;
    for (const auto& l : body.spec->links) links += (links.empty() ? "" : ", ") + l;
    link.comment("URDF links lumped into this body: " + links);
  }
  XmlElement& inertial = link.child("inertial");
  inertial.text_child("mass", body.mass_kg);
  XmlElement& inertia = inertial.child("inertia");
  const Eigen::Matrix3d& I = body.inertia_kg_m2;
  inertia.text_child("ixx", I(0, 0));
  inertia.text_child("ixy", I(0, 1));
  inertia.text_child("ixz", I(0, 2));
  inertia.text_child("iyy", I(1, 1));
  inertia.text_child("iyz", I(1, 2));
  inertia.text_child("izz", I(2, 2));
  const RobotModel& robot = input.model;
  for (std::size_t k = 0; k < body.spec->collisions.size(); ++k) {
    const CollisionShape& shape = body.spec->collisions[k];
    XmlElement& geom = link.child("collision");
    geom.attribute("name", detail::shape_geom_name(shape, k));
    const Eigen::Isometry3d pose = detail::exported_shape_pose(body, shape.X_BG, offset_m);
    geom.text_child("pose", pose_text(pose.translation(), pose.linear()));
    detail::add_sdf_geometry(geom, shape, mesh_uri(robot, shape));
    if (shape.contact != GroundContact::kFall) add_surface(geom, input.parameters);
  }
  const std::vector<VisualShape> visuals = detail::exported_visuals(robot, body, offset_m);
  for (std::size_t k = 0; k < visuals.size(); ++k) {
    const VisualShape& shape = visuals[k];
    XmlElement& geom = link.child("visual");
    geom.attribute("name", detail::visual_geom_name(body.spec->name, shape, k));
    geom.text_child("pose", pose_text(shape.X_BG.translation(), shape.X_BG.linear()));
    detail::add_sdf_geometry(geom, shape, mesh_uri(robot, shape));
    const std::string rgba = detail::visual_rgba(shape);
    XmlElement& material = geom.child("material");
    material.text_child("ambient", rgba);
    material.text_child("diffuse", rgba);
  }
}

struct AxisValues {
  double lower_rad = -kUnlimited_rad;
  double upper_rad = kUnlimited_rad;
  double effort_nm = -1.0;  // SDF: negative = not enforced
  double velocity_rad_s = -1.0;
  double damping = 0.0;
  double friction = 0.0;
  double spring = 0.0;
};

void add_axis(XmlElement& joint, const char* name, const Eigen::Vector3d& axis,
              const AxisValues& v) {
  XmlElement& a = joint.child(name);
  a.text_child("xyz", format_vector(axis)).attribute("expressed_in", "__model__");
  XmlElement& dynamics = a.child("dynamics");
  dynamics.text_child("damping", v.damping);
  dynamics.text_child("friction", v.friction);
  dynamics.text_child("spring_reference", 0.0);
  dynamics.text_child("spring_stiffness", v.spring);
  XmlElement& limit = a.child("limit");
  limit.text_child("lower", v.lower_rad);
  limit.text_child("upper", v.upper_rad);
  limit.text_child("effort", v.effort_nm);
  limit.text_child("velocity", v.velocity_rad_s);
}

AxisValues actuated_axis(const ActuatorExport& a) {
  AxisValues v;
  if (a.limited) {
    v.lower_rad = a.lower_rad;
    v.upper_rad = a.upper_rad;
  }
  v.effort_nm = a.effort_nm;
  v.velocity_rad_s = a.velocity_rad_s > 0.0 ? a.velocity_rad_s : -1.0;
  v.damping = a.damping_nm_s_per_rad;
  v.friction = a.friction_nm;
  return v;
}

void add_servo_extension(XmlElement& joint, const ActuatorExport& a, const std::string& servo) {
  XmlElement& element = joint.child("motoflex:servo");
  element.attribute("joint", a.joint)
      .attribute("kp_nm_per_rad", a.kp_nm_per_rad)
      .attribute("kv_nm_s_per_rad", a.kv_nm_s_per_rad)
      .attribute("effort_nm", a.effort_nm)
      .attribute(a.prismatic ? "armature_kg" : "armature_kg_m2", a.armature)
      .attribute("reduction", a.reduction);
  // The bench's armature is already in the arm link's inertia (as in motoflex's ODE body).
  if (servo_law(servo).point_mass_arm) element.attribute("armature_in_child_link", "true");
}

void add_joint(XmlElement& model, const ExportInput& input, const JointSpec& spec,
               const std::vector<ActuatorExport>& actuators, const FlexExport& flex,
               const Eigen::Vector3d& offset_m) {
  const RobotModel& robot = input.model;
  XmlElement& joint = model.child("joint");
  const bool two_axes = spec.kind == JointKind::kUniversal || spec.kind == JointKind::kFlex;
  joint.attribute("name", spec.name)
      .attribute("type", two_axes                          ? "universal"
                         : spec.kind == JointKind::kSlider ? "prismatic"
                                                           : "revolute");
  joint.text_child("parent", robot.bodies[spec.parent_body].name);
  joint.text_child("child", robot.bodies[spec.child_body].name);
  joint.text_child("pose", pose_text(spec.anchor_W0_m + offset_m, Eigen::Matrix3d::Identity()))
      .attribute("relative_to", "__model__");
  if (spec.kind == JointKind::kFlex) {
    AxisValues v;
    v.damping = flex.damping_nm_s_per_rad;
    v.friction = flex.friction_nm;
    v.spring = flex.spring_nm_per_rad;
    add_axis(joint, "axis", spec.axis1_W0, v);
    add_axis(joint, "axis2", spec.axis2_W0, v);
    joint.child("physics").child("ode").text_child("implicit_spring_damper", "true");
    return;
  }
  const auto axis_values = [&](int actuator) {
    return actuator >= 0 ? actuated_axis(actuators[actuator]) : AxisValues{};
  };
  add_axis(joint, "axis", spec.axis1_W0, axis_values(spec.actuator1));
  if (two_axes) add_axis(joint, "axis2", spec.axis2_W0, axis_values(spec.actuator2));
  for (const int actuator : {spec.actuator1, spec.actuator2}) {
    if (actuator >= 0) {
      add_servo_extension(joint, actuators[actuator],
                          actuator_servo_name(input.model, input.servo, actuator));
    }
  }
}

}  // namespace

std::string export_sdf(const ExportInput& input) {
  const RobotModel& robot = input.model;
  const std::vector<ActuatorExport> actuators = export_actuators(input);
  const FlexExport flex = export_flex(input);
  const Eigen::Vector3d offset = detail::placement_offset_m(
      robot, std::vector<double>(robot.actuators.size(), 0.0), robot.initial_clearance_m);
  const std::vector<ExportedBody> bodies = detail::exported_bodies(input, offset, true);

  XmlElement sdf("sdf");
  sdf.attribute("version", "1.9").attribute("xmlns:motoflex", kMotoflexXmlNamespace);
  sdf.comment(detail::export_header(input, "") +
              ". Joint dynamics and limits are the fitted joint-level values; <motoflex:servo> "
              "(ignored by simulators) holds the linearised servo gains and the armature, which "
              "SDF cannot express.");
  sdf.comment(provenance_comment(input.provenance, input.servo));
  XmlElement& world = sdf.child("world");
  world.attribute("name", "motoflex_" + robot.name);
  world.text_child("gravity", "0 0 -9.81");
  add_physics(world, input);
  bool has_feet = false;
  for (const auto& body : robot.bodies) {
    for (const auto& shape : body.collisions) {
      has_feet = has_feet || shape.contact != GroundContact::kFall;
    }
  }
  if (has_feet) add_ground(world, input);

  XmlElement& model = world.child("model");
  model.attribute("name", robot.name);
  for (const ExportedBody& body : bodies) add_link(model, body, input, offset);
  if (robot.fixed_base) {
    XmlElement& weld = model.child("joint");
    weld.attribute("name", robot.bodies[robot.root_body].name + "_to_world")
        .attribute("type", "fixed");
    weld.text_child("parent", "world");
    weld.text_child("child", robot.bodies[robot.root_body].name);
  }
  for (const JointSpec& spec : robot.joints) {
    add_joint(model, input, spec, actuators, flex, offset);
  }
  return "<?xml version=\"1.0\"?>\n" + sdf.to_string();
}

}  // namespace motoflex
