#include "float_body_state.hpp"

namespace motoflex::detail {
namespace {

dReal to_float(dReal value) {
  return static_cast<dReal>(static_cast<float>(value));
}

}  // namespace

void round_body_state_to_float(dBodyID body) {
  const dReal* position_m = dBodyGetPosition(body);
  dBodySetPosition(body, to_float(position_m[0]), to_float(position_m[1]), to_float(position_m[2]));
  // dBodySetQuaternion renormalises the rounded components (in double).
  const dReal* q = dBodyGetQuaternion(body);
  const dQuaternion rounded = {to_float(q[0]), to_float(q[1]), to_float(q[2]), to_float(q[3])};
  dBodySetQuaternion(body, rounded);
  const dReal* velocity_m_s = dBodyGetLinearVel(body);
  dBodySetLinearVel(body, to_float(velocity_m_s[0]), to_float(velocity_m_s[1]),
                    to_float(velocity_m_s[2]));
  const dReal* rate_rad_s = dBodyGetAngularVel(body);
  dBodySetAngularVel(body, to_float(rate_rad_s[0]), to_float(rate_rad_s[1]),
                     to_float(rate_rad_s[2]));
}

}  // namespace motoflex::detail
