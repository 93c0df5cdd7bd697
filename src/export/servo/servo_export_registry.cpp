#include <vector>

#include "motoflex/core/error.hpp"
#include "motoflex/export/servo_export.hpp"

namespace motoflex {

// Each rule's file defines its entry; a new law's export is its file plus one line per list.
ServoExportRule motoflex_servo_export_rule();
ServoExportRule velocity_servo_export_rule();
ServoExportRule ideal_servo_export_rule();
ServoExportRule bench_servo_export_rule();
ServoExportRule pd_torque_servo_export_rule();
ServoExportRule dynamixel_servo_export_rule();
ServoExportRule feetech_servo_export_rule();

const ServoExportRule& servo_export_rule(const std::string& law) {
  static const std::vector<ServoExportRule> rules = {
      motoflex_servo_export_rule(), velocity_servo_export_rule(),  ideal_servo_export_rule(),
      bench_servo_export_rule(),    pd_torque_servo_export_rule(), dynamixel_servo_export_rule(),
      feetech_servo_export_rule(),
  };
  for (const ServoExportRule& rule : rules) {
    if (rule.law == law) return rule;
  }
  throw ModelError("servo '" + law + "' has no export rule (src/export/servo/)");
}

}  // namespace motoflex
