// The nomad driver against the emulated server with the kit's faults on its
// TCP connection: a server that says nothing refuses the subscription
// within the reply timeout; a connection that goes dead loses the robot and
// finds it again; lost bytes and noise cost at most a reconnection. The
// stream has no sync byte and no checksum (nomad.md §1.1), so a damaged
// reply is found by its length or its silence, and each exchange drops
// what is left of it before asking again.

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <string>

#include "drivers/driver_harness_test_support.hpp"
#include "families/nomad/emulator/nomad_emulator.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/nomad.hpp"

namespace playerkit::drivers::testing {
namespace nomad_faults_test {

using emulators::NomadEmulator;

LineOptions tcp_with(emulators::FaultPlan plan) { return {.tcp = true, .symlink = {}, .faults = plan}; }

struct Robot {
  explicit Robot(emulators::FaultPlan plan)
      : line([] { return std::make_unique<NomadEmulator>(); }, tcp_with(plan)) {
    devices.builtin.logger.set_level(core::LogLevel::kDebug);
    devices.load("nomad:0 ( driver \"nomad\" port \"$PORT\" )\n", line.port());
  }
  core::Device& nomad() { return devices.device(protocol::kNomadCode); }

  EmulatedLine<NomadEmulator> line;
  ConfiguredDevices devices;
};

TEST(NomadFaults, AServerThatSaysNothingRefusesTheSubscriptionWithinTheTimeout) {
  emulators::FaultPlan plan;
  plan.silent_start = std::chrono::seconds(30);
  Robot robot(plan);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_FALSE(robot.nomad().subscribe());
  EXPECT_LT(std::chrono::steady_clock::now() - start, 6s);  // two tries of 2 s
  EXPECT_FALSE(robot.devices.log.first_with({"CONNECT_ROBOT", "is Nserver or robotd running"}).empty())
      << robot.devices.log.all();
}

// A server deaf and mute for 0.5 s after each connection (the kit's
// slow-start; robotd still starting): CONNECT_ROBOT asked again is answered.
TEST(NomadFaults, AServerSlowToWakeIsAskedAgain) {
  emulators::FaultPlan plan;
  plan.slow_start = std::chrono::milliseconds(500);
  Robot robot(plan);
  ASSERT_TRUE(robot.nomad().subscribe()) << robot.devices.log.all();
  EXPECT_TRUE(more_data(robot.nomad(), 3)) << robot.devices.log.all();
}

TEST(NomadFaults, AConnectionThatGoesDeadLosesTheRobotAndFindsItAgain) {
  emulators::FaultPlan plan;
  plan.vanish_at = std::chrono::seconds(1);
  plan.vanish_for = std::chrono::seconds(2);
  Robot robot(plan);
  ASSERT_TRUE(robot.nomad().subscribe()) << robot.devices.log.all();
  EXPECT_FALSE(robot.devices.log.first_with({"lost", "no reply"}, 10s).empty()) << robot.devices.log.all();
  EXPECT_FALSE(robot.nomad().available());
  const std::uint64_t during = data_sequence(robot.nomad());
  EXPECT_FALSE(more_data(robot.nomad(), 1, 300ms)) << "no data while it is lost";
  EXPECT_GE(data_sequence(robot.nomad()), during);
  EXPECT_FALSE(robot.devices.log.first_with({"answers again"}, 10s).empty()) << robot.devices.log.all();
  EXPECT_TRUE(more_data(robot.nomad(), 3)) << robot.devices.log.all();
  // Found again without zeroing: the robot keeps its odometry.
  EXPECT_EQ(robot.line.with([](NomadEmulator& e) { return e.requests_of(hardware::nomad::message_type::kZero); }), 1U);
}

TEST(NomadFaults, LostBytesCostAReconnectionAtMost) {
  emulators::FaultPlan plan;
  plan.drop = 0.0005;  // about one reply in ten loses a byte
  Robot robot(plan);
  ASSERT_TRUE(robot.nomad().subscribe()) << robot.devices.log.all();
  EXPECT_TRUE(eventually([&] { return robot.line.runner().stats().faults.dropped_bytes > 0; }, 15s));
  EXPECT_TRUE(more_data(robot.nomad(), 3, 10s)) << robot.devices.log.all();
}

TEST(NomadFaults, NoiseAndCutRepliesAreSkippedAndTheDataGoesOn) {
  emulators::FaultPlan plan;
  plan.garbage = 0.1;
  plan.truncate = 0.05;
  plan.bad_checksum = 0.5;  // nothing to corrupt: Nclient has no checksum
  Robot robot(plan);
  ASSERT_TRUE(eventually([&] { return robot.nomad().subscribe(); }, 20s)) << robot.devices.log.all();
  EXPECT_TRUE(eventually(
      [&] {
        const auto faults = robot.line.runner().stats().faults;
        return faults.garbage_runs > 0 && faults.truncated > 0;
      },
      20s));
  EXPECT_TRUE(more_data(robot.nomad(), 5, 10s)) << robot.devices.log.all();
}

}  // namespace nomad_faults_test
}  // namespace playerkit::drivers::testing
