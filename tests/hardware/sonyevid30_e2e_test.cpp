// A client of lib/client points an emulated Sony EVI-D30 at a sequence of
// targets through a real server, configured as the manual's sonyevid30
// section; the angles it reads back must be the targets (the wire's whole
// degrees), and the camera's own position the target to within one of its
// units (1/8.8 degree of pan, 1/12 of tilt).

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/sonyevid30/emulator/evid30_emulator.hpp"
#include "families/sonyevid30/protocol/evid30_units.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/ptz.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace sonyevid30_e2e_test {

using namespace std::chrono_literals;
using emulators::Evid30Emulator;
namespace visca = hardware::sonyevid30;

constexpr protocol::DeviceAddress kPtz{protocol::kPtzCode, 0};

struct Target {
  std::int16_t pan;   // degrees
  std::int16_t tilt;  // degrees
  std::int16_t fov;   // degrees
};

std::optional<protocol::PtzData> read_until_at(client::Client& client, Target target, std::chrono::seconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < until) {
    const auto message = client.read(100ms);
    if (!message || message->type() != protocol::MessageType::kData || message->device() != kPtz) continue;
    const auto data = protocol::decode<protocol::PtzData>(message->payload);
    if (data.pan == target.pan && data.tilt == target.tilt && data.zoom == target.fov) return data;
  }
  return std::nullopt;
}

TEST(Sonyevid30EndToEnd, AClientPointsTheCameraAtTargetsThroughTheServerAndReadsBackWhereItIs) {
  emulators::EmulatorRunner camera(std::make_unique<Evid30Emulator>(), emulators::PtyEndpoint{});
  testing::TestServer server("ptz:0 ( driver \"sonyevid30\" port \"" + camera.device_path() + "\" fov [3 30] )\n", {},
                             0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPtz, protocol::Access::kAll).access, protocol::Access::kAll);

  // Both directions on both axes, the limits of each, zoom from tele to wide, and home.
  for (const Target target : {Target{30, 10, 20}, Target{-45, -7, 12}, Target{100, 25, 3}, Target{-100, -25, 30},
                              Target{17, -3, 25}, Target{0, 0, 30}}) {
    const protocol::PtzCommand command{.pan = target.pan, .tilt = target.tilt, .zoom = target.fov, .panspeed = 0,
                                       .tiltspeed = 0};
    client.write_command(kPtz, protocol::encode(command));
    ASSERT_TRUE(read_until_at(client, target, 20s))
        << "never reported at pan " << target.pan << ", tilt " << target.tilt << ", fov " << target.fov;
    const auto [pan, tilt] = camera.with_emulator<Evid30Emulator>([](Evid30Emulator& e) {
      return std::pair{e.pan_units(), e.tilt_units()};
    });
    EXPECT_NEAR(-pan / visca::kPanUnitsPerDegree, target.pan, 1 / visca::kPanUnitsPerDegree) << "pan " << target.pan;
    EXPECT_NEAR(tilt / visca::kTiltUnitsPerDegree, target.tilt, 1 / visca::kTiltUnitsPerDegree) << "tilt " << target.tilt;
  }
}

}  // namespace sonyevid30_e2e_test
}  // namespace playerkit
