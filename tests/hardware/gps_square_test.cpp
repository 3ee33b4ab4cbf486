// A client of lib/client drives an emulated Pioneer around a square through
// a real server while a GPS receiver rides on it (garminnmea.md's emulator,
// geo-referenced in the southern hemisphere); the gps device's UTM traces
// the square, each fix within a centimetre of where the robot truly was when
// the receiver made it.

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "client/client.hpp"
#include "client/typed/position.hpp"
#include "drivers/builtin.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/garminnmea/emulator/garminnmea_emulator.hpp"
#include "families/garminnmea/protocol/utm.hpp"
#include "families/p2os/emulator/p2os_robot_emulator.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/gps.hpp"
#include "protocol/messages/position.hpp"
#include "square_drive.hpp"
#include "test_server.hpp"

namespace playerkit {
namespace gps_square_test {

using namespace std::chrono_literals;
using emulators::EmulatorRunner;
using emulators::PtyEndpoint;

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};
constexpr protocol::DeviceAddress kGps{protocol::kGpsCode, 0};
// Christchurch, New Zealand: UTM zone 59 south.
constexpr double kOriginLatitude = -43.5321;
constexpr double kOriginLongitude = 172.6362;
constexpr double kPeriod = 0.1;                    // s between fixes
constexpr std::int64_t kFirstFix = 1087302919;     // the emulator's 2004-06-15 12:35:19 UTC

struct PioneerWithGps {
  EmulatorRunner robot{std::make_unique<emulators::P2osRobotEmulator>(robot_options()), PtyEndpoint{}};
  std::mutex mutex;
  std::vector<geometry::Pose2> truth;  // where the robot was at each fix, in order
  EmulatorRunner gps{std::make_unique<emulators::GarminNmeaEmulator>(gps_options()), PtyEndpoint{}};

  static emulators::P2osEmulatorOptions robot_options() {
    emulators::P2osEmulatorOptions options;
    options.subclass = "p3dx";
    return options;
  }
  emulators::GarminNmeaGenerated gps_options() {
    emulators::GarminNmeaGenerated options;
    options.origin_latitude = kOriginLatitude;
    options.origin_longitude = kOriginLongitude;
    options.period = std::chrono::milliseconds(100);
    options.decimals = 7;
    options.pose_source = [this] {
      const geometry::Pose2 pose = true_pose();
      std::lock_guard lock(mutex);
      truth.push_back(pose);
      return pose;
    };
    return options;
  }
  geometry::Pose2 true_pose() {
    return robot.with_emulator<emulators::P2osRobotEmulator>(
        [](emulators::P2osRobotEmulator& pioneer) { return pioneer.true_pose(); });
  }
  std::optional<geometry::Pose2> truth_at(std::size_t fix) {
    std::lock_guard lock(mutex);
    return fix < truth.size() ? std::optional(truth[fix]) : std::nullopt;
  }
};

TEST(GpsSquare, TheGpsOfARobotDrivingASquareTracesItInUtm) {
  PioneerWithGps hardware;
  testing::TestServer server("position:0 ( driver \"p2os_position\" port \"" + hardware.robot.device_path() + "\" )\n"
                             "gps:0 ( driver \"garminnmea\" port \"" + hardware.gps.device_path() +
                                 "\" dgps_enable 0 )\n",
                             {}, 0, [](core::DriverRegistry& registry) { drivers::register_builtin_drivers(registry); });
  auto client = client::Client::connect("127.0.0.1", server.port(), 5s);
  client.set_timeout(15s);
  ASSERT_EQ(client.request_access(kPosition, protocol::Access::kAll).access, protocol::Access::kAll);
  ASSERT_EQ(client.request_access(kGps, protocol::Access::kRead).access, protocol::Access::kRead);
  std::vector<protocol::GpsData> fixes;
  const hardware_test::SquareDrive drive = hardware_test::drive_square(client, {}, [&](const protocol::Message& message) {
    if (message.type() == protocol::MessageType::kData && message.device() == kGps) {
      fixes.push_back(protocol::decode<protocol::GpsData>(message.payload));
    }
  });
  ASSERT_TRUE(drive.finished) << drive.failure;

  // Every fix the client read is where the robot was when the receiver made
  // it: UTM metres of the origin's zone are the map's metres.
  const auto origin = hardware::garminnmea::to_utm(kOriginLatitude, kOriginLongitude);
  ASSERT_EQ(origin.zone, 59);
  ASSERT_FALSE(origin.north);
  ASSERT_GT(fixes.size(), 50u);
  double min_east = 1e9, max_east = -1e9, min_north = 1e9, max_north = -1e9;
  std::size_t checked = 0;
  for (const protocol::GpsData& fix : fixes) {
    ASSERT_EQ(fix.quality, 1);
    const double since_first = static_cast<double>(static_cast<std::int64_t>(fix.time_sec) - kFirstFix) +
                               fix.time_usec / 1e6;
    const auto index = static_cast<std::size_t>(std::lround(since_first / kPeriod));
    const auto truth = hardware.truth_at(index);
    ASSERT_TRUE(truth) << "fix " << index;
    const double east = fix.utm_e / 100.0 - origin.easting;
    const double north = fix.utm_n / 100.0 - origin.northing;
    EXPECT_NEAR(east, truth->x, 0.01) << "fix " << index;
    EXPECT_NEAR(north, truth->y, 0.01) << "fix " << index;
    min_east = std::min(min_east, east);
    max_east = std::max(max_east, east);
    min_north = std::min(min_north, north);
    max_north = std::max(max_north, north);
    ++checked;
  }
  EXPECT_GT(checked, 50u);
  // The square: 1 m east, 1 m north, back west and south to the start.
  EXPECT_NEAR(min_east, 0.0, 0.05);
  EXPECT_NEAR(max_east, 1.0, 0.1);
  EXPECT_NEAR(min_north, 0.0, 0.05);
  EXPECT_NEAR(max_north, 1.0, 0.1);
  const protocol::GpsData& last = fixes.back();
  EXPECT_NEAR(last.utm_e / 100.0 - origin.easting, 0.0, 0.1);
  EXPECT_NEAR(last.utm_n / 100.0 - origin.northing, 0.0, 0.1);
}

}  // namespace gps_square_test
}  // namespace playerkit
