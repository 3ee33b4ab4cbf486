#include "drivers/sim/simulated_drivers.hpp"
#include "interfaces/ptz_limits.hpp"
#include "interfaces/ptz_requests.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/ptz.hpp"

namespace playerkit::drivers::sim {

namespace {

// Stage 1.3's head: pan within its limit either way, tilt fixed at 0, the
// field of view between the lens' narrowest and widest.
interfaces::PtzLimits head_limits(const playerkit::sim::PtzSpec& spec) {
  return {-spec.pan_limit, spec.pan_limit, 0.0, 0.0, spec.min_fov, spec.max_fov};
}

}  // namespace

void SimPtzDriver::apply_command(World& world, const core::Command& command) {
  const auto wanted = decode_padded<protocol::PtzCommand>(command.payload);
  const auto& spec = std::get<playerkit::sim::PtzSpec>(world.spec(model()).params);
  const interfaces::PtzPose target = interfaces::ptz_target(wanted, head_limits(spec));
  world.command_ptz(model(), target.pan, target.tilt, target.fov);
}

double SimPtzDriver::reading_time(const World& world) const { return world.ptz(model()).time; }

std::optional<std::vector<std::uint8_t>> SimPtzDriver::encode_reading(const World& world) {
  const playerkit::sim::PtzReading& reading = world.ptz(model());
  return protocol::encode(interfaces::ptz_data({reading.pan, reading.tilt, reading.fov}));
}

core::RequestResult SimPtzDriver::answer(World& /*world*/, const core::Request& request) {
  // The head goes where it is told at once: position control is all there is.
  class SimulatedHead final : public interfaces::PtzHead {
   public:
    bool set_control_mode(std::uint8_t mode) override { return mode == protocol::kPtzPositionControl; }
  };
  SimulatedHead head;
  return interfaces::answer_ptz_request(head, request);
}

}  // namespace playerkit::drivers::sim
