#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/ptz.hpp"

namespace playerkit::drivers::sim {

void SimPtzDriver::apply_command(World& world, const core::Command& command) {
  const auto wanted = decode_padded<protocol::PtzCommand>(command.payload);
  // The world clamps pan to the head's limits and the zoom between its lens' fields of view.
  world.command_ptz(model(), radians(wanted.pan), radians(wanted.tilt), radians(wanted.zoom));
}

double SimPtzDriver::reading_time(const World& world) const { return world.ptz(model()).time; }

std::optional<std::vector<std::uint8_t>> SimPtzDriver::encode_reading(const World& world) {
  const playerkit::sim::PtzReading& reading = world.ptz(model());
  protocol::PtzData data;
  data.pan = wire_value<std::int16_t>(degrees(reading.pan));
  data.tilt = wire_value<std::int16_t>(degrees(reading.tilt));
  data.zoom = wire_value<std::int16_t>(degrees(reading.fov));
  return protocol::encode(data);
}

core::RequestResult SimPtzDriver::answer(World& /*world*/, const core::Request& request) {
  // The head goes where it is told at once: position control is all there is.
  if (request.subtype() == protocol::kPtzControlModeReq && request.payload.size() >= 2 &&
      request.payload[1] == protocol::kPtzPositionControl) {
    return core::RequestResult::ack();
  }
  return core::RequestResult::nack();
}

}  // namespace playerkit::drivers::sim
