#pragma once
// What every simulated device does (sim_drivers.hpp lists them): an
// event-loop driver on one model of a SimulationHost's world. While
// subscribed its model is active (Stage computes a device's data only while
// someone reads it, and moves a robot only while its position device is
// subscribed). Every server cycle it applies the newest command. After every
// step of the world (on the stepping thread) it publishes its model's
// reading, as the Player 1.5 struct, stamped with the reading's simulation
// time, when that time has advanced: a recorder or amcl gets every reading
// at any speedup, a paused world publishes nothing new, and a reading taken
// before the subscription is never sent. Requests are answered with the
// world locked.

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "core/device.hpp"
#include "core/driver.hpp"
#include "core/shared_connection.hpp"
#include "drivers/sim/simulation_host.hpp"
#include "drivers/sim/wire_units.hpp"
#include "sim/world/world.hpp"

namespace playerkit::drivers::sim {

using playerkit::sim::ModelId;
using playerkit::sim::World;

class SimulatedDevice : public core::Driver, private StepObserver {
 public:
  // `activates`: whether subscribing makes the model active (a truth device
  // only watches, and must not set its robot moving).
  SimulatedDevice(std::shared_ptr<SimulationHost> host, ModelId model, bool activates = true);
  ~SimulatedDevice() override;

  void prepare() override { host_->start(); }
  void setup() override;
  void shutdown() override;
  void update() final;
  core::RequestResult handle_request(const core::Request& request) final;

  [[nodiscard]] ModelId model() const { return model_; }
  [[nodiscard]] SimulationHost& host() const { return *host_; }

 protected:
  // With the world locked.
  virtual void apply_command(World& /*world*/, const core::Command& /*command*/) {}
  // The simulation time of the model's current reading.
  [[nodiscard]] virtual double reading_time(const World& world) const = 0;
  // The reading as the interface's data struct; nothing when there is none.
  [[nodiscard]] virtual std::optional<std::vector<std::uint8_t>> encode_reading(const World& world) = 0;
  // A request; NACK unless overridden.
  virtual core::RequestResult answer(World& world, const core::Request& request);
  // After the last subscription went (the world resets what it resets too).
  virtual void unsubscribed() {}
  // Readings up to `time` are not published (a reconfigured scan waits for
  // its first scan in the new layout).
  void skip_readings_until(double time);

 private:
  void stepped(World& world) final;

  std::shared_ptr<SimulationHost> host_;
  const ModelId model_;
  const bool activates_;
  core::SharedConnection::Use use_;
  // No reading at or before it is published. Under the world's lock once set up.
  double published_until_ = -1.0;
};

// A payload zero-extended (or cut) to T's size, then decoded: clients send
// short structs, as 1.5's drivers tolerated.
template <class T>
[[nodiscard]] T decode_padded(const std::vector<std::uint8_t>& payload);

}  // namespace playerkit::drivers::sim

#include "protocol/binary_codec.hpp"

namespace playerkit::drivers::sim {

template <class T>
T decode_padded(const std::vector<std::uint8_t>& payload) {
  std::vector<std::uint8_t> padded(T::kWireSize, 0);
  std::copy_n(payload.begin(), std::min(payload.size(), T::kWireSize), padded.begin());
  return protocol::decode<T>(padded);
}

}  // namespace playerkit::drivers::sim
