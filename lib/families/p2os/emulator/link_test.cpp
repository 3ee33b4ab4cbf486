// What the line does to the robot: noise, corrupt frames, bytes split
// anywhere, wrong baud rates, a host that falls silent.

#include "families/p2os/emulator/test_support.hpp"

namespace playerkit::emulators {
namespace link_test {

using namespace testing;
namespace command = hw::command;
using hw::Command;

std::vector<std::uint8_t> frame_of(const Command& c) { return hw::command_frame(c); }

std::vector<std::uint8_t> corrupted(std::vector<std::uint8_t> frame) {
  frame.back() ^= 0x5A;
  return frame;
}

TEST(P2osLink, GarbageAndBadChecksumsAreIgnoredWithoutLosingSync) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.write(hex("13 37 FB FA 00 FA"));
  host.send(command::sync0);
  host.write(corrupted(frame_of(Command::plain(command::sync1))));
  host.write(hex("FA FB 01 FA FB 02"));  // headers with impossible lengths
  host.send(command::sync1);
  host.write(hex("00 00 00"));
  host.send(command::sync2);
  auto packets = host.take_packets();
  ASSERT_EQ(packets.size(), 3u);
  EXPECT_EQ(packets[0], hex("00"));
  EXPECT_EQ(packets[1], hex("01"));
  EXPECT_EQ(packets[2][0], 0x02);
  EXPECT_EQ(robot.counters().bad_checksums, 1u);
  EXPECT_GT(robot.counters().noise_bytes, 10u);

  host.send(command::open);
  host.send(command::enable, 1);
  host.write(corrupted(frame_of(Command::with_integer(command::vel, 500))));  // never obeyed
  host.wait(500ms);
  EXPECT_EQ(robot.true_pose(), geometry::Pose2{});
  host.write(hex("FF FF FF"));
  host.keep_sending(Command::with_integer(command::vel, 100), 1s);
  EXPECT_NEAR(robot.true_pose().x, 0.1, 1e-9);
  EXPECT_EQ(robot.counters().bad_checksums, 2u);
  EXPECT_EQ(robot.packets_received(command::vel), 10u);
}

TEST(P2osLink, FramesSplitAtEveryByteStillArrive) {
  P2osRobotEmulator robot;
  Host host(robot);
  std::vector<std::uint8_t> stream;
  for (const Command& c : {Command::plain(command::sync0), Command::plain(command::sync1),
                           Command::plain(command::sync2), Command::plain(command::open)}) {
    const auto frame = frame_of(c);
    stream.insert(stream.end(), frame.begin(), frame.end());
  }
  for (std::uint8_t byte : stream) host.write({byte});
  EXPECT_TRUE(robot.connected());
  EXPECT_EQ(host.take_packets().size(), 3u);
}

TEST(P2osLink, SeveralFramesInOneWriteAreAllHandled) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  std::vector<std::uint8_t> burst;
  for (const Command& c : {Command::with_integer(command::enable, 1), Command::type_only(command::seto),
                           Command::with_integer(command::vel, 250), Command::with_integer(command::rvel, 10)}) {
    const auto frame = frame_of(c);
    burst.insert(burst.end(), frame.begin(), frame.end());
  }
  host.write(burst);
  EXPECT_TRUE(robot.motors_enabled());
  host.wait(1s);
  EXPECT_GT(robot.true_pose().x, 0.2);
  EXPECT_GT(robot.true_pose().yaw, 0.1);
}

TEST(P2osLink, AStrayHeaderWithALargeLengthIsDroppedAfterAWhile) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.write(hex("FA FB C8 00"));  // claims 200 more bytes
  host.send(command::sync0);
  EXPECT_TRUE(host.take_frames().empty()) << "still inside the stray frame";
  EXPECT_LT(robot.next_deadline(), Duration::max());
  host.wait(600ms);
  EXPECT_EQ(host.take_packets(), Frames{hex("00")}) << "the SYNC0 behind it is found";
}

TEST(P2osLink, UndecodableCommandsAreCountedAndIgnored) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.write(hw::build_frame(hex("04 55 01 00")));  // unknown argument type
  host.write(hw::build_frame(hex("0B 3B 2C")));     // argument cut short
  EXPECT_EQ(robot.counters().undecodable, 2u);
  EXPECT_FALSE(robot.motors_enabled());
  host.wait(100ms);
  EXPECT_EQ(host.take_sips().size(), 1u);
}

TEST(P2osLink, BaudIsIgnoredUnlessAModelBaudIsSet) {
  {
    P2osRobotEmulator robot;
    EXPECT_EQ(robot.baud(), 0);
    Host host(robot);
    host.send(Command::plain(command::sync0), 115200);
    EXPECT_EQ(host.take_packets(), Frames{hex("00")});
  }
  P2osEmulatorOptions options;
  options.model_baud = 38400;
  P2osRobotEmulator robot(options);
  EXPECT_EQ(robot.baud(), 38400);
  Host host(robot);
  // The driver's probe: 9600 first, no answer; then 38400.
  for (int attempt = 0; attempt < 5; ++attempt) {
    host.send(Command::plain(command::sync0), 9600);
    host.wait(600ms);
  }
  EXPECT_TRUE(host.take_frames().empty());
  EXPECT_EQ(robot.counters().noise_bytes, 30u);
  host.send(Command::plain(command::sync0), 38400);
  EXPECT_EQ(host.take_packets(), Frames{hex("00")});
  host.send(Command::plain(command::sync0), 0);  // unknown speed (TCP): accepted
  EXPECT_EQ(host.take_packets(), Frames{hex("00")});
}

TEST(P2osLink, BytesAtAWrongBaudSpoilAFrameInProgress) {
  P2osEmulatorOptions options;
  options.model_baud = 9600;
  P2osRobotEmulator robot(options);
  Host host(robot);
  const auto sync0 = frame_of(Command::plain(command::sync0));
  host.write({sync0.begin(), sync0.begin() + 3}, 9600);
  host.write(hex("00"), 19200);
  host.write({sync0.begin() + 3, sync0.end()}, 9600);
  EXPECT_TRUE(host.take_frames().empty());
  host.send(Command::plain(command::sync0), 9600);
  EXPECT_EQ(host.take_packets(), Frames{hex("00")});
}

TEST(P2osLink, WatchdogStopsARobotWhoseHostFellSilent) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.send(command::enable, 1);
  host.send(command::vel, 200);
  host.wait(3s);
  EXPECT_NEAR(robot.true_pose().x, 0.4, 1e-9) << "stopped 2 s after the last packet";
  const auto sips = host.take_sips();
  EXPECT_EQ(sips.size(), 30u) << "SIPs keep flowing";
  EXPECT_EQ(sips.back().left_velocity, 0);
  EXPECT_TRUE(robot.motors_enabled());
  // Any packet rearms it; a fresh velocity moves again.
  host.send(command::vel, 200);
  for (int i = 0; i < 10; ++i) {
    host.wait(1s);
    host.send(command::pulse);
  }
  EXPECT_NEAR(robot.true_pose().x, 2.4, 1e-9);
}

TEST(P2osLink, WatchdogCanBeSwitchedOff) {
  P2osEmulatorOptions options;
  options.watchdog.reset();
  P2osRobotEmulator robot(options);
  Host host(robot);
  host.connect();
  host.send(command::enable, 1);
  host.send(command::vel, 200);
  host.wait(3s);
  EXPECT_NEAR(robot.true_pose().x, 0.6, 1e-9);
}

TEST(P2osLink, IdleRobotHasNoDeadline) {
  P2osRobotEmulator robot;
  EXPECT_EQ(robot.next_deadline(), Duration::max());
  Host host(robot);
  host.connect();
  EXPECT_EQ(robot.next_deadline(), host.now() + 100ms);
}

TEST(P2osLink, TimeNeverRunsBackwards) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.send(command::enable, 1);
  host.send(command::vel, 100);
  host.wait(1s);
  const geometry::Pose2 pose = robot.true_pose();
  robot.advance(Duration{0});
  robot.receive(frame_of(Command::plain(command::pulse)), Duration{0}, 0);
  EXPECT_EQ(robot.true_pose(), pose);
  EXPECT_TRUE(robot.take_output().empty());
}

TEST(P2osLink, BadOptionsAreRefusedWithAReason) {
  auto refused = [](P2osEmulatorOptions options) {
    try {
      P2osRobotEmulator robot(options);
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  P2osEmulatorOptions options;
  options.subclass = "p3dx-sh";
  EXPECT_NE(refused(options).find("p3dx-sh"), std::string::npos);
  options = {};
  options.robot_name = std::string(20, 'r');
  EXPECT_NE(refused(options).find("19"), std::string::npos);
  options = {};
  options.sip_period = Duration::zero();
  EXPECT_FALSE(refused(options).empty());
  options = {};
  options.cmucam_blob = hw::CmucamTracking{.confidence = 255};
  EXPECT_NE(refused(options).find("255"), std::string::npos);
}

}  // namespace link_test
}  // namespace playerkit::emulators
