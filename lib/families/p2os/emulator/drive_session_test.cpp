// A scripted host session: connect, enable the motors, drive with VEL, RVEL
// and VEL2, and compare the emulated robot with the kinematic equations and
// with the odometry a host integrates from the SIPs.

#include "families/p2os/emulator/test_support.hpp"

#include <numbers>

namespace playerkit::emulators {
namespace drive_session_test {

using namespace testing;
namespace command = hw::command;
using hw::Command;
constexpr double kPi = std::numbers::pi;
constexpr double kDegree = kPi / 180.0;

// Pose after driving at constant v (m/s) and ω (rad/s) for t seconds.
geometry::Pose2 kinematic(const geometry::Pose2& start, double v, double omega, double t) {
  if (omega == 0.0) {
    return {start.x + v * t * std::cos(start.yaw), start.y + v * t * std::sin(start.yaw), start.yaw};
  }
  const double r = v / omega;
  const double yaw = start.yaw + omega * t;
  return {start.x + r * (std::sin(yaw) - std::sin(start.yaw)),
          start.y - r * (std::cos(yaw) - std::cos(start.yaw)), geometry::normalize_angle(yaw)};
}

void expect_pose_near(const geometry::Pose2& actual, const geometry::Pose2& expected, double tolerance) {
  EXPECT_NEAR(actual.x, expected.x, tolerance);
  EXPECT_NEAR(actual.y, expected.y, tolerance);
  EXPECT_NEAR(angle_between(actual.yaw, expected.yaw), 0.0, tolerance);
}

struct Session {
  explicit Session(P2osEmulatorOptions options = {}) : robot(options), host(robot), odometry(robot.params()) {
    host.connect();
    host.send(command::enable, 1);
    host.send(Command::type_only(command::seto));
    // The host's odometry starts at its first SIP, as the 1.5 driver's does.
    host.wait(200ms);
    read_sips();
  }
  // Every SIP so far into the host's odometry; returns them.
  std::vector<hw::StandardSip> read_sips() {
    auto sips = host.take_sips();
    for (const auto& sip : sips) odometry.add(sip);
    return sips;
  }
  P2osRobotEmulator robot;
  Host host;
  SipOdometry odometry;
};

TEST(P2osDriveSession, Vel200For5sFollowsTheKinematicsAndTheSipsAgree) {
  P2osEmulatorOptions options;
  options.initial_pose = {1.0, 2.0, 0.3};
  Session s(options);
  EXPECT_TRUE(s.robot.motors_enabled());

  s.host.keep_sending(Command::with_integer(command::vel, 200), 5s);
  const auto moving = s.read_sips();
  s.host.send(command::stop);
  s.host.wait(500ms);
  const auto stopped = s.read_sips();

  expect_pose_near(s.robot.true_pose(), kinematic(options.initial_pose, 0.2, 0.0, 5.0), 1e-9);
  expect_pose_near(s.robot.odometry_pose(), {1.0, 0.0, 0.0}, 1e-9);
  // XPOS is rounded to DistConvFactor (0.485 mm) units.
  EXPECT_NEAR(s.odometry.x, 1000.0, 0.5);
  EXPECT_NEAR(s.odometry.y, 0.0, 0.5);
  EXPECT_NEAR(s.odometry.heading, 0.0, 1e-9);

  ASSERT_EQ(moving.size(), 50u);
  for (const auto& sip : moving) {
    EXPECT_EQ(sip.status, hw::packet_type::sip_moving);
    EXPECT_EQ(sip.left_velocity, 200);
    EXPECT_EQ(sip.right_velocity, 200);
    EXPECT_TRUE(sip.motors_enabled());
  }
  ASSERT_EQ(stopped.size(), 5u);
  EXPECT_EQ(stopped.back().status, hw::packet_type::sip_stopped);
  EXPECT_EQ(stopped.back().left_velocity, 0);
}

TEST(P2osDriveSession, PositionCountersWrapAt4096AndStillIntegrate) {
  Session s;
  s.host.keep_sending(Command::with_integer(command::vel, 400), 10s);  // 4 m = 8247 units
  s.host.send(command::stop);
  s.host.wait(200ms);
  const auto sips = s.read_sips();
  EXPECT_TRUE(std::any_of(sips.begin(), sips.end(), [](const hw::StandardSip& sip) { return sip.x_position < 100; }))
      << "the counter went round";
  for (const auto& sip : sips) EXPECT_LT(sip.x_position, 4096);
  EXPECT_NEAR(s.odometry.x, 4000.0, 0.5);
  expect_pose_near(s.robot.true_pose(), {4.0, 0.0, 0.0}, 1e-9);

  s.host.keep_sending(Command::with_integer(command::vel, -400), 10s);
  s.host.send(command::stop);
  s.host.wait(200ms);
  s.read_sips();
  EXPECT_NEAR(s.odometry.x, 0.0, 0.5);
  expect_pose_near(s.robot.true_pose(), {0.0, 0.0, 0.0}, 1e-9);
}

TEST(P2osDriveSession, RvelTurnsInPlace) {
  Session s;
  s.host.keep_sending(Command::with_integer(command::rvel, 45), 2s);
  const auto turning = s.read_sips();
  s.host.send(command::stop);
  s.host.wait(200ms);
  s.read_sips();
  expect_pose_near(s.robot.true_pose(), {0.0, 0.0, kPi / 2}, 1e-9);
  EXPECT_NEAR(s.odometry.heading, kPi / 2, 0.5 * 0.001534);
  EXPECT_NEAR(s.odometry.x, 0.0, 1e-9);
  ASSERT_FALSE(turning.empty());
  // Wheels at ∓ω/DiffConvFactor: 45°/s → 140.25 mm/s.
  EXPECT_EQ(turning.back().left_velocity, -140);
  EXPECT_EQ(turning.back().right_velocity, 140);

  s.host.keep_sending(Command::with_integer(command::rvel, -30), 6s);  // 90° − 180° = −90°
  s.host.send(command::stop);
  s.host.wait(200ms);
  s.read_sips();
  expect_pose_near(s.robot.true_pose(), {0.0, 0.0, -kPi / 2}, 1e-9);
  // THPOS runs 0 ... 4095: −90° is 3072.
  EXPECT_NEAR(s.odometry.heading, 1.5 * kPi, 0.5 * 0.001534);
}

TEST(P2osDriveSession, SeparateModeArcWithTheReferencesRvelVelVelPattern) {
  Session s;
  // §3.1: the motor packet repeats RVEL, VEL, VEL, one per 100 ms cycle.
  const Duration end = s.host.now() + 3s;
  for (int cycle = 0; s.host.now() < end; ++cycle) {
    if (cycle % 3 == 0) s.host.send(command::rvel, 20);
    else s.host.send(command::vel, 200);
    s.host.wait(100ms);
  }
  s.host.send(command::stop);
  s.host.wait(300ms);
  s.read_sips();
  // The first cycle only turns (VEL comes 100 ms later).
  const geometry::Pose2 turned{0.0, 0.0, 20 * kDegree * 0.1};
  const geometry::Pose2 expected = kinematic(turned, 0.2, 20 * kDegree, 2.9);
  expect_pose_near(s.robot.true_pose(), expected, 1e-9);
  EXPECT_NEAR(s.odometry.x, expected.x * 1000.0, 0.5);
  EXPECT_NEAR(s.odometry.y, expected.y * 1000.0, 0.5);
  EXPECT_NEAR(s.odometry.heading, expected.yaw, 0.001);
}

TEST(P2osDriveSession, Vel2DrivesEachWheel) {
  Session s;
  // Left 10 × 20 = 200 mm/s, right 5 × 20 = 100 mm/s.
  const Command vel2 = Command::with_integer(command::vel2, hw::encode_vel2({.left = 10, .right = 5}));
  s.host.keep_sending(vel2, 2s);
  const auto sips = s.read_sips();
  ASSERT_FALSE(sips.empty());
  EXPECT_EQ(sips.back().left_velocity, 200);
  EXPECT_EQ(sips.back().right_velocity, 100);
  const double wheelbase = 2.0 / 0.0056 / 1000.0;
  const geometry::Pose2 after = kinematic({}, 0.15, (0.1 - 0.2) / wheelbase, 2.0);
  expect_pose_near(s.robot.true_pose(), after, 1e-9);
  EXPECT_NEAR(s.robot.wheel_velocities().left, 0.2, 1e-12);
  EXPECT_NEAR(s.robot.wheel_velocities().right, 0.1, 1e-12);

  const Command back = Command::with_integer(command::vel2, hw::encode_vel2({.left = -5, .right = -5}));
  s.host.keep_sending(back, 1s);
  s.host.send(command::vel2, 0);
  s.host.wait(200ms);
  s.read_sips();
  expect_pose_near(s.robot.true_pose(), kinematic(after, -0.1, 0.0, 1.0), 1e-9);
  EXPECT_NEAR(s.odometry.x, s.robot.odometry_pose().x * 1000.0, 0.5);
  EXPECT_NEAR(s.odometry.y, s.robot.odometry_pose().y * 1000.0, 0.5);
}

TEST(P2osDriveSession, DisabledMotorsIgnoreVelocitiesAndEnable0Stops) {
  P2osRobotEmulator robot;
  Host host(robot);
  host.connect();
  EXPECT_FALSE(robot.motors_enabled()) << "motors start disabled";
  host.keep_sending(Command::with_integer(command::vel, 300), 1s);
  EXPECT_EQ(robot.true_pose(), geometry::Pose2{});
  for (const auto& sip : host.take_sips()) {
    EXPECT_FALSE(sip.motors_enabled());
    EXPECT_EQ(sip.left_velocity, 0);
  }
  host.send(command::enable, 1);
  host.keep_sending(Command::with_integer(command::vel, 300), 1s);
  EXPECT_NEAR(robot.true_pose().x, 0.3, 1e-9);
  host.send(command::enable, 0);
  host.wait(1s);
  EXPECT_NEAR(robot.true_pose().x, 0.3, 1e-9);
  EXPECT_FALSE(robot.motors_enabled());
  host.send(command::enable, 1);
  host.wait(1s);
  EXPECT_NEAR(robot.true_pose().x, 0.3, 1e-9) << "re-enabling does not revive an old setpoint";
}

TEST(P2osDriveSession, SpeedsAreClampedSoNoSipStepExceeds100mm) {
  Session s;
  s.host.keep_sending(Command::with_integer(command::vel, 2000), 2s);
  s.read_sips();  // SipOdometry checks every step is <= 100 mm
  EXPECT_NEAR(s.robot.true_pose().x, 0.99 * 2.0, 1e-9);
  s.host.send(command::stop);
  s.host.keep_sending(Command::with_integer(command::rvel, 1000), 1s);
  EXPECT_NEAR(angle_between(s.robot.true_pose().yaw, 500 * kDegree), 0.0, 1e-9);  // MaxRVel 500°/s
}

TEST(P2osDriveSession, SetoZeroesOdometryNotTheWorld) {
  Session s;
  s.host.keep_sending(Command::with_integer(command::vel, 250), 2s);
  s.host.send(command::stop);
  s.host.send(Command::type_only(command::seto));
  s.host.wait(200ms);
  const auto sips = s.host.take_sips();
  ASSERT_FALSE(sips.empty());
  EXPECT_EQ(sips.back().x_position, 0);
  EXPECT_EQ(sips.back().heading, 0);
  EXPECT_EQ(s.robot.odometry_pose(), geometry::Pose2{});
  EXPECT_NEAR(s.robot.true_pose().x, 0.5, 1e-9);
  EXPECT_EQ(s.robot.packets_received(command::seto), 2u);
}

TEST(P2osDriveSession, OdometryErrorIsSystematicAndSeeded) {
  P2osEmulatorOptions options;
  options.odometry_error.translation_scale = 0.05;
  options.odometry_error.rotation_scale = 0.1;
  {
    Session s(options);
    s.host.keep_sending(Command::with_integer(command::vel, 200), 5s);
    s.host.send(command::stop);
    EXPECT_NEAR(s.robot.true_pose().x, 1.0, 1e-9);
    EXPECT_NEAR(s.robot.odometry_pose().x, 1.05, 1e-9);
    s.host.keep_sending(Command::with_integer(command::rvel, 45), 2s);
    EXPECT_NEAR(s.robot.true_pose().yaw, kPi / 2, 1e-9);
    EXPECT_NEAR(s.robot.odometry_pose().yaw, 1.1 * kPi / 2, 1e-9);
  }
  options.odometry_error = {};
  options.odometry_error.translation_noise = 0.02;
  options.odometry_error.rotation_noise = 0.02;
  auto run = [&](std::uint64_t seed) {
    options.odometry_error.seed = seed;
    Session s(options);
    s.host.keep_sending(Command::with_integer(command::vel, 300), 3s);
    s.host.send(command::stop);
    s.host.wait(200ms);
    EXPECT_NEAR(s.robot.true_pose().x, 0.9, 1e-9);
    return s.host.take_frames();
  };
  const auto first = run(7);
  EXPECT_EQ(run(7), first) << "same seed, same bytes";
  EXPECT_NE(run(8), first);
}

TEST(P2osDriveSession, TenSipsASecondWhateverTheTraffic) {
  Session s;
  s.host.take_frames();
  const Duration end = s.host.now() + 2s;
  int sent = 0;
  while (s.host.now() < end) {
    for (int i = 0; i < 10; ++i, ++sent) s.host.send(command::pulse);
    s.host.wait(7ms);
  }
  EXPECT_GT(sent, 2000);
  EXPECT_EQ(s.host.take_sips().size(), 20u);
}

}  // namespace drive_session_test
}  // namespace playerkit::emulators
