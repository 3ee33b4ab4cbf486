// A client of lib/client drives an emulated Pioneer around a square through
// a real server, reading odometry and laser scans; the emulated robot's true
// pose must end where the commands put it.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <string>
#include <thread>

#include "algorithms/grid/occupancy_grid.hpp"
#include "client/client.hpp"
#include "client/typed/laser.hpp"
#include "client/typed/message_as.hpp"
#include "client/typed/position.hpp"
#include "drivers/builtin.hpp"
#include "families/p2os/emulator/p2os_robot_emulator.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/sick/emulator/sick_lms200_emulator.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "square_drive.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace pioneer_square_test {

using namespace std::chrono_literals;
using emulators::EmulatorRunner;
using emulators::PtyEndpoint;

constexpr double kRoomHalfWidth = 3.0;  // a 6 m x 6 m room around the origin
constexpr double kLaserForward = 0.16;  // the LMS 200 sits 16 cm ahead of the centre
constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};
constexpr protocol::DeviceAddress kLaser{protocol::kLaserCode, 0};

grid::OccupancyGrid box_room() {
  const double resolution = 0.05;
  const int cells = static_cast<int>(2 * (kRoomHalfWidth + 0.5) / resolution);
  grid::OccupancyGrid room(cells, cells, resolution, {-kRoomHalfWidth - 0.5, -kRoomHalfWidth - 0.5},
                           grid::CellState::free);
  for (int row = 0; row < cells; ++row) {
    for (int col = 0; col < cells; ++col) {
      const auto centre = room.cell_centre({col, row});
      if (std::abs(centre.x()) > kRoomHalfWidth || std::abs(centre.y()) > kRoomHalfWidth) {
        room.set(col, row, grid::CellState::occupied);
      }
    }
  }
  return room;
}

struct PioneerWithLaser {
  grid::OccupancyGrid room = box_room();
  EmulatorRunner robot{std::make_unique<emulators::P2osRobotEmulator>(robot_options()), PtyEndpoint{}};
  EmulatorRunner laser{std::make_unique<emulators::SickLms200Emulator>(laser_options()), PtyEndpoint{}};

  emulators::P2osEmulatorOptions robot_options() const {
    emulators::P2osEmulatorOptions options;
    options.subclass = "p3dx";
    options.map = &room;
    return options;
  }
  emulators::SickEmulatorOptions laser_options() {
    emulators::SickEmulatorOptions options;
    options.map = &room;
    options.pose_source = [this] {
      const auto body = robot.with_emulator<emulators::P2osRobotEmulator>(
          [](emulators::P2osRobotEmulator& pioneer) { return pioneer.true_pose(); });
      return body.compose({kLaserForward, 0.0, 0.0});
    };
    return options;
  }
  geometry::Pose2 true_pose() {
    return robot.with_emulator<emulators::P2osRobotEmulator>(
        [](emulators::P2osRobotEmulator& pioneer) { return pioneer.true_pose(); });
  }
};

TEST(PioneerSquare, AClientDrivesTheEmulatedRobotAroundASquareThroughTheServer) {
  PioneerWithLaser hardware;
  // The manual's configuration (section 7.3), ports pointing at the emulators.
  testing::TestServer server("position:0 ( driver \"p2os_position\" port \"" + hardware.robot.device_path() +
                                 "\" )\n"
                                 "laser:0 ( driver \"sicklms200\" port \"" + hardware.laser.device_path() +
                                 "\" )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(10s);
  ASSERT_EQ(client.request_access(kPosition, protocol::Access::kAll).access, protocol::Access::kAll);
  ASSERT_EQ(client.request_access(kLaser, protocol::Access::kRead).access, protocol::Access::kRead);
  const geometry::Pose2 start = hardware.true_pose();
  // Motors start disabled (manual 7.30): drive_square switches them on.
  int scans = 0;
  std::optional<protocol::LaserData> scan_read;
  const hardware_test::SquareDrive drive =
      hardware_test::drive_square(client, {.top_speed = 0.7}, [&](const protocol::Message& message) {
        if (message.type() == protocol::MessageType::kData && message.device() == kLaser) {
          scan_read = protocol::decode<protocol::LaserData>(message.payload);
          ++scans;
        }
      });
  ASSERT_TRUE(drive.finished) << drive.failure;

  // Back where it started, within what closing each leg on 10 Hz odometry
  // allows: whole degrees on the wire, and each stop comes one odometry
  // period plus the client's scheduling delay late. On a loaded machine that
  // delay reaches a few hundred milliseconds; at the slowest turn rate
  // (0.1 rad/s, the slowest the robot's integer wheel speeds still turn at)
  // four turns then overshoot by up to about 0.12 rad.
  const geometry::Pose2 end = hardware.true_pose();
  EXPECT_NEAR(end.x, start.x, 0.1);
  EXPECT_NEAR(end.y, start.y, 0.1);
  EXPECT_NEAR(geometry::angle_difference(end.yaw, start.yaw), 0.0, 0.15);

  // The client's odometry is the robot's motion (no odometry error is
  // configured): it ends where the true pose ends, up to the wire's 1 mm and
  // whole degrees.
  ASSERT_TRUE(drive.odometry);
  const auto& odometry = drive.odometry->pose;
  const geometry::Pose2 moved = start.inverse().compose(end);
  EXPECT_NEAR(odometry.x, moved.x, 0.01);
  EXPECT_NEAR(odometry.y, moved.y, 0.01);
  EXPECT_NEAR(geometry::angle_difference(odometry.yaw, moved.yaw), 0.0, 0.02);

  // Scans arrived all along, and they see the room: the beam straight ahead
  // reads the distance from the laser to the wall it faces.
  EXPECT_GT(scans, 10);
  ASSERT_TRUE(scan_read);
  const auto scan = client::to_si(*scan_read);
  ASSERT_EQ(scan.ranges.size(), 361u);
  const geometry::Pose2 laser_pose = end.compose({kLaserForward, 0.0, 0.0});
  const double ahead = scan.ranges[180];
  // Facing +x again (the start heading): the wall is at x = 3 m.
  EXPECT_NEAR(ahead, kRoomHalfWidth - laser_pose.x, 0.1);
}

}  // namespace pioneer_square_test
}  // namespace playerkit
