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

void SimControlDriver::update() {
  if (const std::optional<core::Command> command = device().take_command(); command && !command->payload.empty()) {
    switch (command->payload.front()) {
      case kRun: host_->resume(); break;
      case kPause: host_->pause(); break;
      case kStep: host_->step(); break;
      default:
        device().logger().warning(device().name() + ": command " + std::to_string(command->payload.front()) +
                                  " ignored (0 run, 1 pause, 2 step)");
        break;
    }
  }
  const double time = host_->time();
  const int state = host_->paused() || host_->run_limit_reached() ? 1 : 0;
  if (time == published_time_ && state == published_state_) return;
  published_time_ = time;
  published_state_ = state;
  protocol::SimulationData data;
  data.data = static_cast<std::uint8_t>(state);
  device().publish(protocol::encode(data), simulation_timestamp(time));
}

}  // namespace playerkit::drivers::sim
