#include "client/typed/ptz.hpp"

#include "client/typed/to_wire.hpp"

namespace playerkit::client {
namespace {

using protocol::WireUnit;

template <class Wire>
PtzState read(const Wire& w) {
  using protocol::to_si;
  return {to_si(WireUnit::kDegree, w.pan), to_si(WireUnit::kDegree, w.tilt), to_si(WireUnit::kDegree, w.zoom),
          to_si(WireUnit::kDegreePerSecond, w.panspeed), to_si(WireUnit::kDegreePerSecond, w.tiltspeed)};
}

}  // namespace

PtzState to_si(const protocol::PtzData& data) { return read(data); }
PtzState to_si(const protocol::PtzCommand& command) { return read(command); }

protocol::PtzCommand to_wire(const PtzCommand& c) {
  protocol::PtzCommand w;
  w.pan = to_wire<std::int16_t>(WireUnit::kDegree, c.pan, "ptz command pan");
  w.tilt = to_wire<std::int16_t>(WireUnit::kDegree, c.tilt, "ptz command tilt");
  w.zoom = to_wire<std::int16_t>(WireUnit::kDegree, c.zoom, "ptz command zoom");
  w.panspeed = to_wire<std::int16_t>(WireUnit::kDegreePerSecond, c.pan_speed, "ptz command pan_speed");
  w.tiltspeed = to_wire<std::int16_t>(WireUnit::kDegreePerSecond, c.tilt_speed, "ptz command tilt_speed");
  return w;
}

}  // namespace playerkit::client
