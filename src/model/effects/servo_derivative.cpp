#include "effect_builders.hpp"

namespace motoflex::detail {

// The servo firmware also acts on the error's rate (bench law): duty = g·kp·(e + T_d·ė),
// ė = θ̇_d − θ̇. BAM's servo model is P only, but servo firmwares have a D gain beside the P
// gain (the dynamixel and feetech laws' kd register). The D term pushes ahead of a moving goal
// and damps the arm's own motion by an amount that grows with kp and saturates with the duty,
// which no joint friction term does. Neutral at T_d = 0; the probe moves it to 5 ms.
Effect servo_derivative_effect() {
  return {"servo_derivative",
          "the servo firmware's D on the error rate: duty = g*kp*(e + T_d*de/dt)",
          "a servo that lags a moving goal less, and overshoots less after a step, than its P "
          "gain and friction allow, more so at higher gains",
          {global("bench.derivative_s", 0.1, false, 0.0, 0.05)},
          false,
          0};
}

}  // namespace motoflex::detail
