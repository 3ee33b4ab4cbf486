// A client of lib/client reads the blobs an emulated CMUcam2 sees and points
// its servos at a sequence of targets through a real server, configured as
// the manual's cmucam2 section plus a ptz section on the same devicepath.
// The angles read back and the servos' own positions must be the targets
// within the servos' 0.75 degrees, and the blob aimed at must sit in the
// middle of the frame.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <memory>
#include <optional>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/cmucam2/emulator/cmucam2_emulator.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/blobfinder.hpp"
#include "protocol/messages/ptz.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace cmucam2_e2e_test {

using namespace std::chrono_literals;
using emulators::Cmucam2Emulator;

constexpr protocol::DeviceAddress kBlobfinder{protocol::kBlobfinderCode, 0};
constexpr protocol::DeviceAddress kPtz{protocol::kPtzCode, 0};
constexpr std::uint32_t kRed = 0xdc2626;    // color0's middle
constexpr std::uint32_t kGreen = 0x26d226;  // color1's middle
constexpr double kServoDegrees = 0.75;

struct Target {
  std::int16_t pan;  // degrees
  std::int16_t tilt;
  std::optional<std::uint32_t> centred;  // the blob that should then be mid-frame
};

template <class Data, class Condition>
std::optional<Data> read_until(client::Client& client, protocol::DeviceAddress device, Condition condition,
                               std::chrono::seconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < until) {
    const auto message = client.read(100ms);
    if (!message || message->type() != protocol::MessageType::kData || message->device() != device) continue;
    const auto data = protocol::decode<Data>(message->payload);
    if (condition(data)) return data;
  }
  return std::nullopt;
}

const protocol::BlobfinderBlob* blob_of(const protocol::BlobfinderData& data, std::uint32_t color) {
  for (const auto& blob : data.blobs) {
    if (blob.color == color) return &blob;
  }
  return nullptr;
}

TEST(Cmucam2EndToEnd, AClientReadsBlobsAndPointsTheServosAtTargetsThroughTheServer) {
  emulators::EmulatorRunner camera(std::make_unique<Cmucam2Emulator>(Cmucam2Emulator::default_scene()),
                                   emulators::PtyEndpoint{});
  const std::string port = camera.device_path();
  testing::TestServer server("blobfinder:0 ( driver \"cmucam2\" devicepath \"" + port +
                                 "\" num_blobs 2 color0 [200 240 16 60 16 60] color1 [16 60 180 240 16 60] )\n"
                                 "ptz:0 ( driver \"cmucam2\" devicepath \"" + port + "\" )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kBlobfinder, protocol::Access::kRead).access, protocol::Access::kRead);
  ASSERT_EQ(client.request_access(kPtz, protocol::Access::kAll).access, protocol::Access::kAll);

  // Straight ahead: the red disc 10 degrees left (column 26), the green 15 right and 5 up.
  const auto ahead = read_until<protocol::BlobfinderData>(
      client, kBlobfinder, [](const auto& d) { return d.blobs.size() == 2; }, 10s);
  ASSERT_TRUE(ahead);
  EXPECT_NEAR(blob_of(*ahead, kRed)->x, 26, 1);
  EXPECT_GT(blob_of(*ahead, kGreen)->x, 60);

  for (const Target& target : {Target{10, 0, kRed}, Target{-15, 5, kGreen}, Target{30, -20, std::nullopt},
                               Target{-60, 45, std::nullopt}, Target{0, 0, std::nullopt}}) {
    const protocol::PtzCommand command{.pan = target.pan, .tilt = target.tilt, .zoom = 0, .panspeed = 0, .tiltspeed = 0};
    client.write_command(kPtz, protocol::encode(command));
    const auto reached = read_until<protocol::PtzData>(
        client, kPtz,
        [&](const auto& d) { return std::abs(d.pan - target.pan) <= 1 && std::abs(d.tilt - target.tilt) <= 1; }, 10s);
    ASSERT_TRUE(reached) << "never reported at pan " << target.pan << ", tilt " << target.tilt;
    // The servos get there at their own speed; then they sit within a position of the target.
    ASSERT_TRUE(read_until<protocol::PtzData>(
        client, kPtz,
        [&](const auto&) {
          return camera.with_emulator<Cmucam2Emulator>([&](Cmucam2Emulator& e) {
            return std::abs(e.pan_degrees() - target.pan) <= kServoDegrees / 2 &&
                   std::abs(e.tilt_degrees() - target.tilt) <= kServoDegrees / 2;
          });
        },
        5s))
        << "the servos never reached pan " << target.pan << ", tilt " << target.tilt;
    if (!target.centred) continue;
    const auto seen = read_until<protocol::BlobfinderData>(
        client, kBlobfinder,
        [&](const auto& d) {
          const auto* blob = blob_of(d, *target.centred);
          return blob != nullptr && std::abs(blob->x - 44) <= 1 && std::abs(blob->y - 72) <= 2;
        },
        10s);
    EXPECT_TRUE(seen) << "the blob aimed at is not mid-frame at pan " << target.pan;
  }
}

}  // namespace cmucam2_e2e_test
}  // namespace playerkit
