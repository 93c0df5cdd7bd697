#pragma once

#include <string>
#include <vector>

#include "motoflex/studies/titan/titan_paper_study.hpp"

namespace motoflex {

// The TITAN-VIII torque/power study of seed 000 as read from a YAML file
// (scenarios/titan/paper.yaml):
//
//   name: titan8_paper
//   robot: ../robots/titan8          # folder with robot.yaml, relative to this file
//   servo: velocity                  # velocity (eq. 3, the paper's) or ideal
//   physics: {dt_s: 0.001, solver: step, initial_clearance_m: 0.01}
//   contact: {mu: 0.5, slip: 0.001, soft_erp: 0.2, soft_cfm: 1.0e-4}  # §II-D (friction pyramid)
//   parameters: {}                   # any other robot parameter, e.g. joint.FL_J3.gain_per_s
//   commands: {rate_hz: 100, servo_lead: true}
//   static: {posture: A, duration_s: 5, cut_after_touchdown_s: 0.03, converge_fraction: 0.05,
//            converge_reference_nm: 10, final_window_s: 0.5}
//   updown: {posture: A, amplitude_m: 0.03, period_s: 4, periods: 2, settle_s: 0.5}
//   crawl: {postures: [A, B, C, D], periods: 3, settle_s: 0.5, plot_leg: FL,
//           exchange_window_s: [2.4, 4.8]}
//   timing: {crawl_s: 10, posture: A, repeats: 3}
//
// Every key is optional except `robot`; defaults are the paper's. Unknown keys, wrong types and
// out-of-range values throw InputError naming file, line and field.
struct TitanStudyConfig {
  std::string path;
  std::string name;
  TitanPaperStudyPlan plan;
};

TitanStudyConfig load_titan_study_config(const std::string& path);

}  // namespace motoflex
