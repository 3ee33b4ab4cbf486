// A client of lib/client points an emulated PTU-46 at a sequence of targets
// through a real server, configured as the manual's ptu46 section; the angles
// it reads back and the unit's own positions must be the targets, to the
// wire's whole degrees and the unit's 185 arc-seconds.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/ptu46/emulator/ptu46_emulator.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace ptu46_e2e_test {

using namespace std::chrono_literals;
using emulators::Ptu46Emulator;

constexpr protocol::DeviceAddress kPtz{protocol::kPtzCode, 0};

struct Target {
  std::int16_t pan;   // degrees
  std::int16_t tilt;  // degrees
};

// The last state read, once the client has seen the unit at `target`.
std::optional<protocol::PtzData> read_until_at(client::Client& client, Target target, std::chrono::seconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < until) {
    const auto message = client.read(100ms);
    if (!message || message->type() != protocol::MessageType::kData || message->device() != kPtz) continue;
    const auto data = protocol::decode<protocol::PtzData>(message->payload);
    if (data.pan == target.pan && data.tilt == target.tilt) return data;
  }
  return std::nullopt;
}

TEST(Ptu46EndToEnd, AClientPointsTheUnitAtTargetsThroughTheServerAndReadsBackWhereItIs) {
  // The unit's top speed as its power-up speed: a 300-degree swing takes
  // two seconds instead of six (speed 0 in a command keeps the unit's).
  emulators::Ptu46EmulatorOptions unit_options;
  unit_options.start_speed = unit_options.upper_speed;
  emulators::EmulatorRunner unit(std::make_unique<Ptu46Emulator>(unit_options), emulators::PtyEndpoint{});
  testing::TestServer server("ptz:0 ( driver \"ptu46\" port \"" + unit.device_path() + "\" )\n", {}, 0,
                             [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPtz, protocol::Access::kAll).access, protocol::Access::kAll);

  const double degrees_per_position = unit_options.resolution_arc_seconds / 3600.0;
  // Both directions on both axes, the tilt's two unequal limits nearly reached
  // (-46.6 and +31.1 degrees), and back home.
  for (const Target target : {Target{30, -10}, Target{-45, 20}, Target{150, -45}, Target{-150, 30}, Target{0, 0}}) {
    const protocol::PtzCommand command{.pan = target.pan, .tilt = target.tilt, .zoom = 0, .panspeed = 0, .tiltspeed = 0};
    client.write_command(kPtz, protocol::encode(command));
    ASSERT_TRUE(read_until_at(client, target, 20s)) << "never reported at pan " << target.pan << ", tilt " << target.tilt;
    // Positions are whole steps: a demand in degrees lands within one step.
    const auto [pan, tilt] = unit.with_emulator<Ptu46Emulator>([](Ptu46Emulator& ptu) {
      return std::pair{ptu.position(Ptu46Emulator::Axis::pan), ptu.position(Ptu46Emulator::Axis::tilt)};
    });
    EXPECT_NEAR(pan * degrees_per_position, target.pan, degrees_per_position) << "pan " << target.pan;
    EXPECT_NEAR(tilt * degrees_per_position, target.tilt, degrees_per_position) << "tilt " << target.tilt;
  }
}

}  // namespace ptu46_e2e_test
}  // namespace playerkit
