#include "robot_yaml.hpp"

namespace motoflex::detail {
namespace {

void read_identity(const YamlValue& root, RobotYaml& out) {
  out.name = root.at("name").as_string();
  out.urdf_path = root.resolve_path(root.at("urdf").as_string());
}

void read_base(const YamlValue& root, RobotYaml& out) {
  out.root_link = root.get_string("root_link", "");
  out.torso_link = root.get_string("torso_link", out.root_link);
  out.fixed_base = root.get_bool("fixed_base", false);
}

void read_servo(const YamlValue& root, RobotYaml& out) {
  const YamlValue servo = root.at("servo");
  out.servo = servo.as_string();
  out.servo_line = servo.line();
}

void read_actuated(const YamlValue& root, RobotYaml& out, ErrorCollector& errors) {
  const YamlValue list = root.at("actuated_joints");
  const std::vector<YamlValue> items = list.items();
  if (items.empty()) list.fail("at least one actuated joint needed");
  for (const YamlValue& item : items) {
    errors.check([&] {
      item.require_keys_within({"joint", "group"});
      out.actuated.push_back({item.at("joint").as_string(), item.at("group").as_string(), item});
    });
  }
}

// (The lambdas name the loop's structured bindings in init-captures: clang before 16 cannot
// capture a structured binding, and scripts/fuzz builds with clang.)
// `servos:` maps an actuated joint or a gear/servo group to a servo law.
void read_servos(const YamlValue& root, RobotYaml& out, ErrorCollector& errors) {
  const auto servos = root.find("servos");
  if (!servos) return;
  for (const auto& [key, law] : servos->entries()) {
    errors.check([&, &key = key, &law = law] {
      out.servos.push_back({key, law.as_string(), law});
    });
  }
}

void read_structure(const YamlValue& root, RobotYaml& out, ErrorCollector& errors) {
  errors.check([&] {
    if (const auto held = root.find("held_joints")) {
      for (const auto& [joint, angle] : held->entries()) {
        errors.check([&, &joint = joint, &angle = angle] { out.held[joint] = angle.as_double(); });
      }
    }
  });
  errors.check([&] {
    if (const auto pairs = root.find("universal_joints")) {
      for (const YamlValue& pair : pairs->items()) {
        errors.check([&] {
          const auto names = pair.as_string_list();
          if (names.size() != 2) pair.fail("expected a pair [first_joint, second_joint]");
          out.universal_pairs.emplace_back(names[0], names[1]);
        });
      }
    }
  });
  errors.check([&] {
    if (const auto links = root.find("flexible_links"))
      out.flexible_links = links->as_string_list();
  });
  errors.check([&] {
    if (const auto split = root.find("flexible_split")) {
      const std::string how = split->as_string();
      if (how != "span" && how != "box") split->fail("expected 'span' or 'box'");
      out.flexible_split_box = how == "box";
    }
  });
  errors.check([&] { out.joint_stops = root.get_bool("joint_stops", true); });
  errors.check([&] { out.ground = root.get_bool("ground", true); });
  errors.check([&] {
    if (const auto limits = root.find("joint_limits")) {
      for (const auto& [joint, range] : limits->entries()) {
        errors.check([&, &joint = joint, &range = range] {
          const auto pair = range.as_double_list();
          if (pair.size() != 2 || !(pair[0] < pair[1])) range.fail("expected [lower, upper]");
          out.joint_limits.push_back({joint, pair[0], pair[1], range});
        });
      }
    }
  });
}

void read_contacts(const YamlValue& root, RobotYaml& out, ErrorCollector& errors) {
  const std::pair<const char*, std::vector<std::string>*> lists[] = {
      {"feet", &out.feet},
      {"contact_links", &out.contact_links},
      {"trimesh_links", &out.trimesh_links},
      {"capsule_links", &out.capsule_links}};
  for (const auto& [key, list] : lists) {
    errors.check([&, key = key, list = list] {
      if (const auto value = root.find(key)) *list = value->as_string_list();
    });
  }
  errors.check([&] {
    if (const auto fall = root.find("fall")) {
      fall->require_keys_within({"max_tilt_rad", "min_torso_height_m"});
      out.max_tilt_rad = fall->get_double("max_tilt_rad", out.max_tilt_rad);
      out.min_torso_height_m = fall->get_double("min_torso_height_m", out.min_torso_height_m);
    }
  });
  errors.check([&] {
    out.initial_clearance_m = root.get_double("initial_clearance_m", out.initial_clearance_m);
  });
}

void read_stand_pose(const YamlValue& root, RobotYaml& out, ErrorCollector& errors) {
  if (const auto pose = root.find("stand_pose")) {
    for (const auto& [joint, angle] : pose->entries()) {
      errors.check(
          [&, &joint = joint, &angle = angle] { out.stand_pose[joint] = angle.as_double(); });
    }
  }
}

}  // namespace

RobotYaml read_robot_yaml(const YamlValue& root, ErrorCollector& errors) {
  root.check_keys_within({"name",
                          "urdf",
                          "root_link",
                          "fixed_base",
                          "torso_link",
                          "servo",
                          "servos",
                          "actuated_joints",
                          "held_joints",
                          "universal_joints",
                          "flexible_links",
                          "flexible_split",
                          "feet",
                          "contact_links",
                          "trimesh_links",
                          "capsule_links",
                          "joint_stops",
                          "ground",
                          "joint_limits",
                          "fall",
                          "initial_clearance_m",
                          "stand_pose",
                          "parameters"},
                         errors);
  RobotYaml out;
  errors.check([&] { read_identity(root, out); });
  errors.check([&] { read_base(root, out); });
  errors.check([&] { read_servo(root, out); });
  errors.check([&] { read_actuated(root, out, errors); });
  errors.check([&] { read_servos(root, out, errors); });
  read_structure(root, out, errors);
  read_contacts(root, out, errors);
  errors.check([&] { read_stand_pose(root, out, errors); });
  return out;
}

}  // namespace motoflex::detail
