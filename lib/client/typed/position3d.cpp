#include "client/typed/position3d.hpp"

#include "client/typed/to_wire.hpp"

namespace playerkit::client {
namespace {

using protocol::WireUnit;

// Data and command share the field names of these twelve values.
template <class Wire>
void read_motion(const Wire& w, Pose3D& pose, Velocity3D& velocity) {
  using protocol::to_si;
  pose = {to_si(WireUnit::kMillimetre, w.xpos),   to_si(WireUnit::kMillimetre, w.ypos),
          to_si(WireUnit::kMillimetre, w.zpos),   to_si(WireUnit::kArcSecond, w.roll),
          to_si(WireUnit::kArcSecond, w.pitch),   to_si(WireUnit::kArcSecond, w.yaw)};
  velocity = {to_si(WireUnit::kMillimetrePerSecond, w.xspeed), to_si(WireUnit::kMillimetrePerSecond, w.yspeed),
              to_si(WireUnit::kMillimetrePerSecond, w.zspeed), to_si(WireUnit::kArcSecondPerSecond, w.rollspeed),
              to_si(WireUnit::kArcSecondPerSecond, w.pitchspeed),
              to_si(WireUnit::kArcSecondPerSecond, w.yawspeed)};
}

}  // namespace

Position3dState to_si(const protocol::Position3dData& data) {
  Position3dState state;
  read_motion(data, state.pose, state.velocity);
  state.stall = data.stall != 0;
  return state;
}

Position3dCommand to_si(const protocol::Position3dCommand& command) {
  Position3dCommand si;
  read_motion(command, si.target, si.velocity);
  return si;
}

protocol::Position3dCommand to_wire(const Position3dCommand& c) {
  auto length = [](double v, const char* field) { return to_wire<std::int32_t>(WireUnit::kMillimetre, v, field); };
  auto angle = [](double v, const char* field) { return to_wire<std::int32_t>(WireUnit::kArcSecond, v, field); };
  auto speed = [](double v, const char* field) {
    return to_wire<std::int32_t>(WireUnit::kMillimetrePerSecond, v, field);
  };
  auto rate = [](double v, const char* field) {
    return to_wire<std::int32_t>(WireUnit::kArcSecondPerSecond, v, field);
  };
  protocol::Position3dCommand w;
  w.xpos = length(c.target.x, "position3d command target.x");
  w.ypos = length(c.target.y, "position3d command target.y");
  w.zpos = length(c.target.z, "position3d command target.z");
  w.roll = angle(c.target.roll, "position3d command target.roll");
  w.pitch = angle(c.target.pitch, "position3d command target.pitch");
  w.yaw = angle(c.target.yaw, "position3d command target.yaw");
  w.xspeed = speed(c.velocity.x, "position3d command velocity.x");
  w.yspeed = speed(c.velocity.y, "position3d command velocity.y");
  w.zspeed = speed(c.velocity.z, "position3d command velocity.z");
  w.rollspeed = rate(c.velocity.roll, "position3d command velocity.roll");
  w.pitchspeed = rate(c.velocity.pitch, "position3d command velocity.pitch");
  w.yawspeed = rate(c.velocity.yaw, "position3d command velocity.yaw");
  return w;
}

}  // namespace playerkit::client
