#include "robot_parameters.hpp"

#include "parameter_catalog.hpp"

namespace motoflex::detail {

void read_robot_parameters(const YamlValue& root, RobotModel& model, ErrorCollector& errors) {
  errors.check([&] {
    const YamlValue parameters = root.at("parameters");
    model.source.parameters_line = parameters.line();
    for (const auto& [name, value] : parameters.entries()) {
      errors.check([&, &name = name, &value = value] {
        const auto triple = value.as_double_list();
        if (triple.size() != 3) value.fail("expected [default, lower, upper]");
        if (!(triple[1] < triple[2])) value.fail("lower bound must be below the upper bound");
        if (triple[0] < triple[1] || triple[0] > triple[2]) {
          value.fail("default must lie within [lower, upper]");
        }
        model.parameters.add(
            {name, unit_from_parameter_name(name), triple[0], triple[1], triple[2]});
        model.source.parameter_lines[name] = value.line();
      });
    }
  });
  for (const auto& spec : effect_parameter_specs(model)) {
    if (!model.parameters.contains(spec.name)) model.parameters.add(spec);
  }
}

}  // namespace motoflex::detail
