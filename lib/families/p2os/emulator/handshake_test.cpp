// The connection life cycle of p2os.md §2.4 and §6.3-6.5, byte for byte.

#include "families/p2os/emulator/test_support.hpp"

namespace playerkit::emulators {
namespace handshake_test {

using namespace testing;
namespace command = hw::command;

P2osEmulatorOptions my_robot() {
  P2osEmulatorOptions options;
  options.robot_name = "MyRobot";
  options.subclass = "p3dx";
  return options;
}

TEST(P2osHandshake, ByteForByteAsTheSheetPrintsIt) {
  P2osRobotEmulator robot(my_robot());
  Host host(robot);
  host.wait(1s);
  EXPECT_TRUE(host.take_frames().empty()) << "nothing unsolicited before the handshake";

  host.write(hex("FA FB 03 00 00 00"));
  EXPECT_EQ(host.take_frames(), Frames{hex("FA FB 03 00 00 00")});
  EXPECT_EQ(robot.link_state(), P2osLinkState::got_sync0);

  host.write(hex("FA FB 03 01 00 01"));
  EXPECT_EQ(host.take_frames(), Frames{hex("FA FB 03 01 00 01")});

  host.write(hex("FA FB 03 02 00 02"));
  EXPECT_EQ(host.take_frames(),
            Frames{hex("FA FB 18 02 4D 79 52 6F 62 6F 74 00 50 69 6F 6E 65 65 72 00 70 33 "
                            "64 78 00 43 DF")});
  EXPECT_EQ(robot.link_state(), P2osLinkState::synced);
  EXPECT_FALSE(robot.connected());

  host.write(hex("FA FB 03 01 00 01"));  // OPEN
  EXPECT_TRUE(robot.connected());
  EXPECT_TRUE(host.take_frames().empty()) << "commands are never acknowledged";
  host.wait(99ms);
  EXPECT_TRUE(host.take_frames().empty());
  host.wait(1ms);
  EXPECT_EQ(host.take_sips().size(), 1u) << "the first SIP one period after OPEN";
  host.wait(1s);
  EXPECT_EQ(host.take_sips().size(), 10u);
}

TEST(P2osHandshake, Sync2ReplyNamesTheClaimedRow) {
  P2osEmulatorOptions options;
  options.subclass = "P2AT8+";  // any case selects the row; the reply spells it as the table
  P2osRobotEmulator robot(options);
  Host host(robot);
  const hw::Sync2Reply reply = host.synchronise();
  EXPECT_EQ(reply.name, "playerkit");
  EXPECT_EQ(reply.robot_class, "Pioneer");
  EXPECT_EQ(reply.subclass, "p2at8+");
  EXPECT_EQ(&hw::select_robot_params(reply.robot_class, reply.subclass), &robot.params());
}

TEST(P2osHandshake, StepsOutOfOrderGetNoReply) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.send(command::sync1);
  host.send(command::sync2);
  host.send(command::enable, 1);
  host.send(command::vel, 100);
  EXPECT_TRUE(host.take_frames().empty());
  EXPECT_EQ(robot.link_state(), P2osLinkState::unconnected);
  EXPECT_EQ(robot.counters().ignored, 3u);  // SYNC2 unanswered counts as a CLOSE

  host.send(command::sync0);
  host.send(command::sync2);  // not after SYNC1: back to the start
  EXPECT_EQ(host.take_packets(), Frames{hex("00")});
  EXPECT_EQ(robot.link_state(), P2osLinkState::unconnected);
  host.send(command::sync1);
  EXPECT_TRUE(host.take_frames().empty());
}

TEST(P2osHandshake, AnySync0RestartsTheSequence) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.send(command::sync0);
  host.send(command::sync1);
  host.send(command::sync0);  // restart after SYNC1
  host.send(command::sync0);  // a stale extra SYNC0 is harmless
  EXPECT_EQ(host.take_packets(), (Frames{hex("00"), hex("01"), hex("00"), hex("00")}));
  EXPECT_EQ(robot.link_state(), P2osLinkState::got_sync0);
  host.send(command::sync1);
  host.send(command::sync2);
  host.send(command::sync0);  // and after SYNC2
  const auto packets = host.take_packets();
  ASSERT_EQ(packets.size(), 3u);
  EXPECT_EQ(packets[2], hex("00"));
  EXPECT_EQ(robot.link_state(), P2osLinkState::got_sync0);
  host.send(command::open);  // OPEN (= SYNC1) now only continues the handshake
  EXPECT_FALSE(robot.connected());
}

TEST(P2osHandshake, OpenBeforeSync2IsNotAConnection) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.send(command::open);
  host.wait(500ms);
  EXPECT_FALSE(robot.connected());
  EXPECT_TRUE(host.take_frames().empty());
}

TEST(P2osHandshake, CloseStopsSipsAtOnceAndReturnsToUnconnected) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.send(command::enable, 1);
  host.send(command::vel, 300);
  host.wait(550ms);
  EXPECT_EQ(host.take_sips().size(), 5u);
  host.send(command::close);
  EXPECT_FALSE(robot.connected());
  EXPECT_FALSE(robot.motors_enabled());
  EXPECT_EQ(robot.wheel_velocities(), (mobile_base::WheelVelocities{0.0, 0.0}));
  const geometry::Pose2 stopped = robot.true_pose();
  host.wait(2s);
  EXPECT_TRUE(host.take_frames().empty());
  EXPECT_EQ(robot.true_pose(), stopped);
  EXPECT_EQ(robot.next_deadline(), Duration::max());

  // The next session redoes the whole handshake, motors disabled again.
  host.connect();
  host.send(command::vel, 300);
  host.wait(300ms);
  EXPECT_EQ(robot.true_pose(), stopped);
  const auto sips = host.take_sips();
  ASSERT_FALSE(sips.empty());
  EXPECT_FALSE(sips.back().motors_enabled());
}

TEST(P2osHandshake, ARestartedDriverFindsTheRobotStreamingAndClosesIt) {
  // §2.4 step 3b: the driver's SYNC0 meets a SIP stream (SYNC0 is PULSE
  // while connected); it sends CLOSE, waits, flushes and syncs again.
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.wait(1s);
  host.take_frames();

  host.send(command::sync0);
  host.wait(400ms);
  const auto packets = host.take_packets();
  ASSERT_FALSE(packets.empty());
  EXPECT_TRUE(hw::is_standard_sip(packets.front()[0]));
  host.send(command::close);
  host.wait(400ms);
  host.take_frames();  // the flush
  EXPECT_EQ(host.synchronise().robot_class, "Pioneer");
  host.send(command::open);
  host.wait(200ms);
  EXPECT_EQ(host.take_sips().size(), 2u);
}

TEST(P2osHandshake, ClosingThePortEndsTheSession) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.send(command::enable, 1);
  host.send(command::vel, 200);
  host.wait(300ms);
  robot.host_disconnected(host.now());
  EXPECT_FALSE(robot.connected());
  EXPECT_EQ(robot.link_state(), P2osLinkState::unconnected);
  host.take_frames();
  host.wait(1s);
  EXPECT_TRUE(host.take_frames().empty());
  host.connect();  // a reopened slave gets a fresh handshake
  EXPECT_TRUE(robot.connected());
}

TEST(P2osHandshake, AHostThatComesBackInTheSameReadAsItsCloseIsAnswered) {
  // The runner may read the old session's goodbye (STOP, ENABLE 0, CLOSE)
  // and the next session's SYNC0 in one go and only then hear that the old
  // host hung up: the hang-up must not wipe the handshake just begun.
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  host.wait(300ms);
  host.take_frames();
  std::vector<std::uint8_t> goodbye_and_hello;
  for (const hw::Command& c : {hw::Command::plain(command::stop), hw::Command::with_integer(command::enable, 0),
                               hw::Command::plain(command::close), hw::Command::plain(command::sync0)}) {
    const auto frame = hw::command_frame(c);
    goodbye_and_hello.insert(goodbye_and_hello.end(), frame.begin(), frame.end());
  }
  host.write(goodbye_and_hello);
  robot.host_disconnected(host.now());
  EXPECT_EQ(host.take_frames(), Frames{hex("FA FB 03 00 00 00")});
  host.send(command::sync1);
  EXPECT_EQ(host.take_frames(), Frames{hex("FA FB 03 01 00 01")}) << robot.describe();
  host.send(command::sync2);
  ASSERT_EQ(host.take_packets().size(), 1u);
  host.send(command::open);
  EXPECT_TRUE(robot.connected());
}

TEST(P2osHandshake, DescribeSaysWhereTheLinkStands) {
  P2osRobotEmulator robot;
  Host host(robot);
  EXPECT_NE(robot.describe().find("waiting for SYNC0"), std::string::npos) << robot.describe();
  host.connect();
  EXPECT_NE(robot.describe().find("connected"), std::string::npos) << robot.describe();
  EXPECT_NE(robot.describe().find("p3dx"), std::string::npos) << robot.describe();
  // The true pose ends the line, as every robot emulator's does.
  EXPECT_NE(robot.describe().find(", at (0.00, 0.00, 0 deg)"), std::string::npos) << robot.describe();
}

}  // namespace handshake_test
}  // namespace playerkit::emulators
