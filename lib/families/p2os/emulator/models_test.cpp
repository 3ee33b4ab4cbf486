// Every row of the parameter table: the robot claims its own subclass in
// SYNC2 and reports motion in that row's units.

#include "families/p2os/emulator/test_support.hpp"

#include <numbers>

namespace playerkit::emulators {
namespace models_test {

using namespace testing;
namespace command = hw::command;
using hw::Command;

TEST(P2osModels, EveryRowNamesItselfAndUsesItsOwnConversions) {
  for (const hw::RobotParams& row : hw::robot_params_table()) {
    SCOPED_TRACE(std::string(row.subclass));
    P2osEmulatorOptions options;
    options.subclass = std::string(row.subclass);
    options.robot_name = "robot" + std::to_string(row.index);
    P2osRobotEmulator robot(options);
    EXPECT_EQ(&robot.params(), &row);
    Host host(robot);

    const hw::Sync2Reply reply = host.synchronise();
    EXPECT_EQ(reply.name, options.robot_name);
    EXPECT_EQ(reply.robot_class, "Pioneer");
    EXPECT_EQ(reply.subclass, row.subclass);
    EXPECT_EQ(&hw::select_robot_params(reply.robot_class, reply.subclass), &row);

    host.send(command::open);
    host.send(command::enable, 1);
    host.wait(200ms);
    SipOdometry odometry(row);
    for (const auto& sip : host.take_sips()) odometry.add(sip);

    // VEL2 5/5: 5 × Vel2Divisor mm/s on each wheel.
    const double speed = 5.0 * row.vel2_divisor;  // mm/s
    host.keep_sending(Command::with_integer(command::vel2, hw::encode_vel2({5, 5})), 1s);
    auto sips = host.take_sips();
    ASSERT_FALSE(sips.empty());
    EXPECT_EQ(sips.back().left_velocity, std::lround(speed / row.vel_conv_factor));
    EXPECT_EQ(sips.back().right_velocity, std::lround(speed / row.vel_conv_factor));
    ASSERT_EQ(static_cast<int>(sips.back().sonar.size()), row.sonar_count);
    EXPECT_EQ(sips.back().sonar.back().range, std::lround(5000.0 / row.range_conv_factor));
    host.send(command::stop);
    host.wait(100ms);
    for (const auto& sip : sips) odometry.add(sip);
    for (const auto& sip : host.take_sips()) odometry.add(sip);
    EXPECT_NEAR(odometry.x, speed * 1.0, row.dist_conv_factor);
    EXPECT_NEAR(robot.true_pose().x, speed / 1000.0, 1e-9);

    // RVEL −30°/s for 1 s: THPOS wraps below 0 to one turn minus 30°.
    host.keep_sending(Command::with_integer(command::rvel, -30), 1s);
    host.send(command::stop);
    host.wait(100ms);
    sips = host.take_sips();
    const double units = 30.0 * std::numbers::pi / 180.0 / row.angle_conv_factor;
    EXPECT_NEAR(sips.back().heading, row.heading_units_per_turn() - units, 0.5 + 1e-6);
  }
}

TEST(P2osModels, SubclassMatchIgnoresCase) {
  P2osEmulatorOptions options;
  options.subclass = "PerfPB+";
  P2osRobotEmulator robot(options);
  EXPECT_EQ(robot.params().subclass, "perfpb+");
  EXPECT_EQ(robot.sonar_array().size(), 32);
}

TEST(P2osModels, RowsWithoutSheetPosesGetAnEvenRing) {
  P2osEmulatorOptions options;
  options.subclass = "powerbot";
  P2osRobotEmulator robot(options);
  const auto poses = robot.sonar_array().poses();
  ASSERT_EQ(poses.size(), 31u);
  EXPECT_EQ(poses[0].heading, 90) << "index 0 faces left";
  EXPECT_LT(poses[1].heading, 90) << "then clockwise";
  EXPECT_EQ(poses[0].x, 0);
  EXPECT_EQ(poses[0].y, 440);  // 80 % of the 550 mm radius
}

}  // namespace models_test
}  // namespace playerkit::emulators
