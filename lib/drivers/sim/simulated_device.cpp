#include "drivers/sim/simulated_device.hpp"

#include <exception>
#include <string>
#include <utility>

namespace playerkit::drivers::sim {

SimulatedDevice::SimulatedDevice(std::shared_ptr<SimulationHost> host, ModelId model, bool activates)
    : host_(std::move(host)), model_(model), activates_(activates) {}

SimulatedDevice::~SimulatedDevice() = default;

void SimulatedDevice::setup() {
  use_ = host_->attach();
  // Only readings taken after this moment: the world takes one at the next step.
  published_until_ = activates_ ? host_->activate(model_) : host_->with_world([](World& world) { return world.time(); });
  host_->observe_steps(this);
}

void SimulatedDevice::shutdown() {
  host_->stop_observing_steps(this);
  if (activates_) host_->deactivate(model_);
  unsubscribed();
  use_ = {};
}

void SimulatedDevice::skip_readings_until(double time) {
  if (time > published_until_) published_until_ = time;
}

void SimulatedDevice::update() {
  std::optional<core::Command> command = device().take_command();
  if (!command) return;
  host_->with_world([&](World& world) {
    try {
      apply_command(world, *command);
    } catch (const std::exception& e) {
      device().logger().warning(device().name() + ": command ignored: " + e.what());
    }
  });
}

void SimulatedDevice::stepped(World& world) {
  const double time = reading_time(world);
  if (time <= published_until_) return;
  std::optional<std::vector<std::uint8_t>> payload = encode_reading(world);
  if (!payload) return;
  published_until_ = time;
  device().publish(std::move(*payload), simulation_timestamp(time));
}

core::RequestResult SimulatedDevice::handle_request(const core::Request& request) {
  return host_->with_world([&](World& world) { return answer(world, request); });
}

core::RequestResult SimulatedDevice::answer(World& /*world*/, const core::Request& /*request*/) {
  return core::RequestResult::nack();
}

}  // namespace playerkit::drivers::sim
