// A robot whose handshake hangs holds up only the client opening it: the
// p2os connection is opened (SYNC0 at every speed until connect_timeout) on
// a thread of the server's background setups, never on its event loop, so
// a client of another device on the same server is served meanwhile.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <future>
#include <string>

#include "client/client.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "emulators/runner/fault_plan.hpp"
#include "families/p2os/emulator/p2os_robot_emulator.hpp"
#include "families/sick/emulator/sick_lms200_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "support/eventually.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace blocking_handshake_test {

using namespace std::chrono_literals;
constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};
constexpr protocol::DeviceAddress kLaser{protocol::kLaserCode, 0};

emulators::FaultPlan silent_for_ever() {
  emulators::FaultPlan plan;
  emulators::add_fault(plan, "silent-start=100000");
  return plan;
}

TEST(BlockingHandshake, AClientOfAnotherDeviceIsServedWhileARobotsHandshakeHangs) {
  emulators::EmulatorRunner robot(std::make_unique<emulators::P2osRobotEmulator>(), emulators::PtyEndpoint{},
                                  silent_for_ever());
  emulators::EmulatorRunner laser(std::make_unique<emulators::SickLms200Emulator>(), emulators::PtyEndpoint{});
  testing::TestServer server("position:0 ( driver \"p2os_position\" port \"" + robot.device_path() +
                                 "\" connect_timeout 10 )\n"
                                 "laser:0 ( driver \"sicklms200\" port \"" + laser.device_path() + "\" )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });

  // The first client opens the robot: its DEV reply waits for the handshake.
  std::atomic<bool> robot_answered{false};
  auto robot_client = std::async(std::launch::async, [&] {
    auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
    client.set_timeout(30s);
    const auto grant = client.request_access(kPosition, protocol::Access::kAll);
    robot_answered = true;
    return grant.access;
  });
  ASSERT_TRUE(testing::eventually([&] { return robot.stats().host_connects >= 1; }, 10s))
      << "the robot's line was never opened";

  // Meanwhile a second client opens the laser and reads a scan.
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kLaser, protocol::Access::kRead).access, protocol::Access::kRead);
  bool scanned = false;
  for (int reads = 0; reads < 100 && !scanned; ++reads) {
    const auto message = client.read(100ms);
    scanned = message && message->type() == protocol::MessageType::kData && message->device() == kLaser;
  }
  EXPECT_TRUE(scanned);
  EXPECT_FALSE(robot_answered) << "the laser's client waited for the robot's handshake";

  // The silent robot is refused at its connect_timeout: 'e'.
  EXPECT_EQ(robot_client.get(), protocol::Access::kError);
}

}  // namespace blocking_handshake_test
}  // namespace playerkit
