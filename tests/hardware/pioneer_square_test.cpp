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

// The latest odometry and scan a client has read.
struct Readings {
  std::optional<client::PositionState> odometry;
  std::optional<protocol::LaserData> scan;
  int scans = 0;

  void take(const protocol::Message& message) {
    if (message.type() != protocol::MessageType::kData) return;
    const protocol::DeviceAddress from = message.device();
    if (from == kPosition) odometry = client::to_si(protocol::decode<protocol::PositionData>(message.payload));
    if (from == kLaser) {
      scan = protocol::decode<protocol::LaserData>(message.payload);
      ++scans;
    }
  }
};

void command(client::Client& client, double speed, double turn_rate) {
  client::PositionCommand wanted;
  wanted.velocity = {speed, 0.0, turn_rate};
  const auto wire = protocol::encode(client::to_wire(wanted));
  client.write_command(kPosition, wire);
}

// Reads until `done` says so or `limit` passes; false on time out.
template <class Done>
bool read_until(client::Client& client, Readings& readings, Done done, std::chrono::seconds limit) {
  const auto until = std::chrono::steady_clock::now() + limit;
  while (std::chrono::steady_clock::now() < until) {
    if (auto message = client.read(100ms)) readings.take(*message);
    if (readings.odometry && done(*readings.odometry)) return true;
  }
  return false;
}

double heading_change(double from, double to) { return geometry::angle_difference(to, from); }

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
  // Motors start disabled (manual 7.30): switch them on.
  const auto power = protocol::encode(protocol::PositionPowerConfig{protocol::kPositionMotorPowerReq, 1});
  ASSERT_EQ(client.request(kPosition, power).type(), protocol::MessageType::kAck);

  Readings readings;
  ASSERT_TRUE(read_until(client, readings, [](const auto&) { return true; }, 10s)) << "no odometry";
  const geometry::Pose2 start = hardware.true_pose();

  // Four sides of 1 m, each followed by a quarter turn left, closed on
  // odometry with a proportional slow-down, as a client program would.
  for (int side = 0; side < 4; ++side) {
    const auto from = *readings.odometry;
    ASSERT_TRUE(read_until(client, readings, [&](const client::PositionState& now) {
      const double left = 1.0 - std::hypot(now.pose.x - from.pose.x, now.pose.y - from.pose.y);
      command(client, std::clamp(1.5 * left, 0.05, 0.7), 0.0);
      return left <= 0.005;
    }, 15s)) << "side " << side;
    command(client, 0.0, 0.0);
    const double heading = readings.odometry->pose.yaw;
    ASSERT_TRUE(read_until(client, readings, [&](const client::PositionState& now) {
      const double left = std::numbers::pi / 2 - heading_change(heading, now.pose.yaw);
      command(client, 0.0, std::clamp(2.0 * left, 0.1, 1.2));
      return left <= 0.01;
    }, 15s)) << "turn " << side;
    command(client, 0.0, 0.0);
  }
  std::this_thread::sleep_for(300ms);
  while (auto message = client.read(10ms)) readings.take(*message);

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
  ASSERT_TRUE(readings.odometry);
  const auto& odometry = readings.odometry->pose;
  const geometry::Pose2 moved = start.inverse().compose(end);
  EXPECT_NEAR(odometry.x, moved.x, 0.01);
  EXPECT_NEAR(odometry.y, moved.y, 0.01);
  EXPECT_NEAR(geometry::angle_difference(odometry.yaw, moved.yaw), 0.0, 0.02);

  // Scans arrived all along, and they see the room: the beam straight ahead
  // reads the distance from the laser to the wall it faces.
  EXPECT_GT(readings.scans, 10);
  ASSERT_TRUE(readings.scan);
  const auto scan = client::to_si(*readings.scan);
  ASSERT_EQ(scan.ranges.size(), 361u);
  const geometry::Pose2 laser_pose = end.compose({kLaserForward, 0.0, 0.0});
  const double ahead = scan.ranges[180];
  // Facing +x again (the start heading): the wall is at x = 3 m.
  EXPECT_NEAR(ahead, kRoomHalfWidth - laser_pose.x, 0.1);
}

}  // namespace pioneer_square_test
}  // namespace playerkit
