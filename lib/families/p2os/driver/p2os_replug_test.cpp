// A robot whose serial adapter is pulled and put back (the line's port
// itself gone, not only silent): the connection notices, keeps its devices
// unavailable while it reopens the port and handshakes, and serves them
// again on the new line; one log line each way.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>

#include "families/p2os/driver/p2os_test_support.hpp"

namespace playerkit::drivers {
namespace p2os_replug_test {

using namespace p2os_testing;

TEST(P2osReplug, ARobotUnpluggedAndPluggedBackIsFoundOnTheReopenedPort) {
  const auto symlink =
      std::filesystem::temp_directory_path() / ("p2os_replug_test_" + std::to_string(::getpid()));
  drivers::testing::EmulatedLine<P2osRobotEmulator> robot([] { return std::make_unique<P2osRobotEmulator>(); },
                                                          {.symlink = symlink});
  RobotDevices devices(robot.port(), "position:0 ( driver \"p2os_position\" port \"$PORT\" sip_timeout 0.5 )\n"
                                     "sonar:0 ( driver \"p2os_sonar\" )\n");
  core::Device& position = devices.position();
  ASSERT_TRUE(position.subscribe()) << devices.log.all();
  ASSERT_TRUE(devices.sonar().subscribe());
  ASSERT_TRUE(more_data(position));

  robot.replug(false);  // pulled
  ASSERT_TRUE(eventually([&] { return !position.available(); }, 10s)) << devices.log.all();
  EXPECT_TRUE(eventually([&] { return !devices.sonar().available(); }, 1s));

  robot.replug();  // put back: a fresh robot on the same name
  ASSERT_TRUE(eventually([&] { return position.available(); }, 15s)) << devices.log.all();
  EXPECT_TRUE(devices.sonar().available());
  EXPECT_TRUE(more_data(position, 3));
  EXPECT_TRUE(more_data(devices.sonar(), 3));
  EXPECT_EQ(devices.log.count("lost the robot", core::LogLevel::kWarning), 1u) << devices.log.all();
  EXPECT_EQ(devices.log.count("the robot is back after", core::LogLevel::kWarning), 1u) << devices.log.all();
  EXPECT_EQ(devices.counter(position, "robot_lost"), 1u);
  EXPECT_EQ(devices.counter(position, "reconnects"), 1u);
}

}  // namespace p2os_replug_test
}  // namespace playerkit::drivers
