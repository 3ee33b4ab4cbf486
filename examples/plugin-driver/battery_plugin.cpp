// A driver plugin: a simulated battery on the `power` interface, loaded with
//
//   player-serve -d ./libplayerkit_battery_plugin.so battery.cfg
//
// It shows the three things a plugin needs: a driver class, a factory that
// reads the driver's options from its config section, and the entry point
// (PLAYERKIT_DRIVER_PLUGIN) that registers it.

#include <algorithm>
#include <chrono>
#include <cmath>

#include "core/driver.hpp"
#include "core/plugin.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/power.hpp"

namespace {

using namespace playerkit;

// Voltage falls linearly from `volts` at `drain` volts per second, reported
// `rate` times per second.
class SimulatedBattery final : public core::ThreadedDriver {
 public:
  SimulatedBattery(double volts, double drain, double rate)
      : start_volts_(volts), drain_(drain), period_(std::chrono::duration<double>(1.0 / rate)) {}

 protected:
  void run(std::stop_token stop) override {
    const auto start = std::chrono::steady_clock::now();
    do {
      const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const double volts = std::max(0.0, start_volts_ - drain_ * elapsed);
      protocol::PowerData data;
      data.charge = static_cast<std::uint16_t>(std::lround(volts * 10.0));  // decivolts
      device().publish(protocol::encode(data));
      device().service_requests();  // power has no requests we know: NACK them
    } while (sleep_for(stop, std::chrono::duration_cast<std::chrono::nanoseconds>(period_)));
  }

 private:
  double start_volts_;
  double drain_;
  std::chrono::duration<double> period_;
};

}  // namespace

PLAYERKIT_DRIVER_PLUGIN(registry) {
  registry.add(core::DriverSpec{
      .name = "simbattery",
      .interfaces = {protocol::kPowerCode},
      .access = protocol::Access::kRead,
      .factory = [](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
        const double rate = context.section.read_float("rate", 10.0);
        if (!(rate > 0.0)) throw std::invalid_argument("rate must be positive");
        return std::make_unique<SimulatedBattery>(context.section.read_float("volts", 13.0),
                                                  context.section.read_float("drain", 0.01), rate);
      },
      .limits = {},
      .summary = "simulated battery: voltage falling at a steady rate (example plugin)",
  });
}
