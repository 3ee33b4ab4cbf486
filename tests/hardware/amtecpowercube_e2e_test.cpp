// A client of lib/client points an emulated Amtec PowerCube wrist at a
// sequence of targets through a real server, configured as the manual's
// amtecpowercube section; the angles it reads back once the wrist has
// stopped must be the targets to the wire's whole degree, and the modules'
// own positions the targets to a float's resolution.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/amtecpowercube/emulator/powercube_emulator.hpp"
#include "families/amtecpowercube/protocol/powercube_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace amtecpowercube_e2e_test {

using namespace std::chrono_literals;
using emulators::PowercubeEmulator;
using Module = PowercubeEmulator::Module;

constexpr protocol::DeviceAddress kPtz{protocol::kPtzCode, 0};

struct Target {
  std::int16_t pan;   // degrees, Player's convention
  std::int16_t tilt;  // degrees
};

// The first state read with the wrist at `target` and both modules still.
std::optional<protocol::PtzData> read_until_stopped_at(client::Client& client, Target target, std::chrono::seconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < until) {
    const auto message = client.read(100ms);
    if (!message || message->type() != protocol::MessageType::kData || message->device() != kPtz) continue;
    const auto data = protocol::decode<protocol::PtzData>(message->payload);
    if (data.pan == target.pan && data.tilt == target.tilt && data.panspeed == 0 && data.tiltspeed == 0) return data;
  }
  return std::nullopt;
}

TEST(AmtecPowercubeEndToEnd, AClientPointsTheWristAtTargetsThroughTheServerAndReadsBackWhereItIs) {
  // Powered up away from home: the driver's homing brings it to 0, 0 first.
  emulators::PowercubeEmulatorOptions wrist_options{.pan_start = 25, .tilt_start = -15};
  emulators::EmulatorRunner wrist(std::make_unique<PowercubeEmulator>(wrist_options), emulators::PtyEndpoint{});
  // The emulated modules' top speed, so that half-turn swings take seconds.
  testing::TestServer server("ptz:0 ( driver \"amtecpowercube\" port \"" + wrist.device_path() + "\" speed 90 home 1 )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPtz, protocol::Access::kAll).access, protocol::Access::kAll);
  ASSERT_TRUE(read_until_stopped_at(client, {0, 0}, 20s)) << "never reported homed at 0, 0";

  // Both directions on both axes, half-turn pan swings, and back home.
  for (const Target target : {Target{30, -10}, Target{-45, 20}, Target{150, -45}, Target{-150, 60}, Target{0, 0}}) {
    const protocol::PtzCommand command{.pan = target.pan, .tilt = target.tilt, .zoom = 0, .panspeed = 0, .tiltspeed = 0};
    client.write_command(kPtz, protocol::encode(command));
    ASSERT_TRUE(read_until_stopped_at(client, target, 20s)) << "never reported at pan " << target.pan << ", tilt " << target.tilt;
    const auto [pan, tilt] = wrist.with_emulator<PowercubeEmulator>([](PowercubeEmulator& cube) {
      return std::pair{hardware::powercube::degrees(cube.position(Module::pan)),
                       hardware::powercube::degrees(cube.position(Module::tilt))};
    });
    // The pan module counts clockwise; positions travel as float32 radians.
    EXPECT_NEAR(-pan, target.pan, 1e-4) << "pan " << target.pan;
    EXPECT_NEAR(tilt, target.tilt, 1e-4) << "tilt " << target.tilt;
  }
}

}  // namespace amtecpowercube_e2e_test
}  // namespace playerkit
