#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/power.hpp"

namespace playerkit::drivers::sim {

namespace {

protocol::PowerData power_data(const playerkit::sim::PowerReading& reading) {
  protocol::PowerData data;
  data.charge = wire_value<std::uint16_t>(reading.volts * 10.0);  // decivolts
  return data;
}

}  // namespace

double SimPowerDriver::reading_time(const World& world) const { return world.power(model()).time; }

std::optional<std::vector<std::uint8_t>> SimPowerDriver::encode_reading(const World& world) {
  return protocol::encode(power_data(world.power(model())));
}

core::RequestResult SimPowerDriver::answer(World& world, const core::Request& request) {
  if (request.subtype() != protocol::kMainPowerReq) return core::RequestResult::nack();
  return core::RequestResult::ack(protocol::encode(power_data(world.power(model()))));
}

}  // namespace playerkit::drivers::sim
