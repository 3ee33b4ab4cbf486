#include <utility>

#include "drivers/sim/simulated_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/simulation.hpp"

namespace playerkit::drivers::sim {

SimControlDriver::SimControlDriver(std::shared_ptr<SimulationHost> host) : host_(std::move(host)) {}

void SimControlDriver::setup() {
  use_ = host_->attach();
  published_time_ = -1.0;
  published_state_ = -1;
}

void SimControlDriver::shutdown() { use_ = {}; }

bool SimControlDriver::control(std::uint8_t what) {
  switch (what) {
    case kRun: host_->resume(); return true;
    case kPause: host_->pause(); return true;
    case kStep: host_->step(); return true;
    case kPicture: return host_->write_picture();
    default: return false;
  }
}

std::uint8_t SimControlDriver::state() const { return host_->paused() || host_->run_limit_reached() ? 1 : 0; }

void SimControlDriver::update() {
  if (const std::optional<core::Command> command = device().take_command(); command && !command->payload.empty()) {
    // A picture that could not be written is logged by the host already.
    if (!control(command->payload.front()) && command->payload.front() != kPicture) {
      device().logger().warning(device().name() + ": command " + std::to_string(command->payload.front()) +
                                " ignored (0 run, 1 pause, 2 step, 3 picture)");
    }
  }
  const double time = host_->time();
  const std::uint8_t now = state();
  if (time == published_time_ && now == published_state_) return;
  published_time_ = time;
  published_state_ = now;
  protocol::SimulationData data;
  data.data = now;
  device().publish(protocol::encode(data), simulation_timestamp(time));
}

core::RequestResult SimControlDriver::handle_request(const core::Request& request) {
  if (request.payload.empty() || !control(request.payload.front())) return core::RequestResult::nack();
  protocol::SimulationData data;
  data.data = state();
  return core::RequestResult::ack(protocol::encode(data));
}

}  // namespace playerkit::drivers::sim
