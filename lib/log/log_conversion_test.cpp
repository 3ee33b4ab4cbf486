// CARMEN <-> Player conversion: exact wire values for hand-made records, and
// the intel-corrected Radish log converted to Player messages and back.

#include "log/log_conversion.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <stdexcept>
#include <string>

#include "log/carmen_log_parser.hpp"
#include "log/carmen_log_reader.hpp"
#include "log/carmen_log_writer.hpp"
#include "log/log_input.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/constants.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/laser.hpp"
#include "protocol/messages/position.hpp"
#include "protocol/messages/truth.hpp"

namespace playerkit::log {
namespace log_conversion_test {

using protocol::decode;

CarmenLaser flaser(std::vector<double> ranges) {
  CarmenLaser laser;
  laser.kind = CarmenLaserKind::kFlaser;
  laser.config = guess_carmen_laser_config(ranges.size());
  laser.config_guessed = true;
  laser.ranges = std::move(ranges);
  laser.laser_pose = CarmenPose{1.25, -2.5, std::numbers::pi / 2};
  laser.robot_pose = CarmenPose{1.0, -2.0, std::numbers::pi / 4};
  laser.stamp = {1000.5, "pippo", 12.25};
  return laser;
}

TEST(CarmenToPlayer, FlaserBecomesLaserPositionAndTruth) {
  std::vector<double> ranges(180, 1.234);
  ranges[0] = 0.0;
  ranges[179] = 65.535;
  const auto converted = carmen_to_player(flaser(ranges));
  EXPECT_EQ(converted.host, "pippo");
  ASSERT_EQ(converted.messages.size(), 3u);

  const auto& laser_message = converted.messages[0];
  EXPECT_EQ(laser_message.device(), (protocol::DeviceAddress{protocol::kLaserCode, 0}));
  EXPECT_EQ(laser_message.type(), protocol::MessageType::kData);
  EXPECT_EQ(laser_message.time(), (protocol::Timestamp{12, 250000}));       // logger_timestamp
  EXPECT_EQ(laser_message.timestamp(), (protocol::Timestamp{1000, 500000}));  // ipc_timestamp
  EXPECT_EQ(laser_message.header.size, laser_message.payload.size());
  const auto scan = decode<protocol::LaserData>(laser_message.payload);
  EXPECT_EQ(scan.min_angle, -9000);
  EXPECT_EQ(scan.max_angle, 8900);
  EXPECT_EQ(scan.resolution, 100);
  EXPECT_EQ(scan.range_res, 1);  // 65535 mm still fits
  EXPECT_EQ(scan.range_count, 180);
  EXPECT_EQ(scan.ranges[0], 0);
  EXPECT_EQ(scan.ranges[1], 1234);
  EXPECT_EQ(scan.ranges[179], 65535);

  const auto& position = converted.messages[1];
  EXPECT_EQ(position.device(), (protocol::DeviceAddress{protocol::kPositionCode, 0}));
  const auto odometry = decode<protocol::PositionData>(position.payload);
  EXPECT_EQ(odometry.xpos, 1000);
  EXPECT_EQ(odometry.ypos, -2000);
  EXPECT_EQ(odometry.yaw, 45);

  const auto& truth = converted.messages[2];
  EXPECT_EQ(truth.device(), (protocol::DeviceAddress{protocol::kTruthCode, 0}));
  const auto laser_pose = decode<protocol::TruthData>(truth.payload);
  EXPECT_EQ(laser_pose.px, 1250);
  EXPECT_EQ(laser_pose.py, -2500);
  EXPECT_EQ(laser_pose.pa, 90);
}

TEST(CarmenToPlayer, MaxRangeReadingsUseCentimetres) {
  std::vector<double> ranges(361, 2.005);
  ranges[7] = 81.83;
  const auto converted = carmen_to_player(flaser(ranges));
  const auto scan = decode<protocol::LaserData>(converted.messages[0].payload);
  EXPECT_EQ(scan.range_res, 10);
  EXPECT_EQ(scan.ranges[7], 8183);
  EXPECT_EQ(scan.ranges[0], 201);  // 2.005 m to the nearest cm
  EXPECT_EQ(scan.min_angle, -9000);
  EXPECT_EQ(scan.max_angle, 9000);
  EXPECT_EQ(scan.resolution, 50);
}

TEST(CarmenToPlayer, OdometryParamAndErrors) {
  const auto odom = std::get<CarmenOdometry>(
      std::get<CarmenRecord>(parse_carmen_line("ODOM 0.5 -0.25 3.14159 0.3 -0.5 0 5.5 host 6.5", "t", 1)));
  const auto converted = carmen_to_player(odom);
  ASSERT_EQ(converted.messages.size(), 1u);
  const auto pose = decode<protocol::PositionData>(converted.messages[0].payload);
  EXPECT_EQ(pose.xpos, 500);
  EXPECT_EQ(pose.ypos, -250);
  EXPECT_EQ(pose.yaw, 180);
  EXPECT_EQ(pose.xspeed, 300);
  EXPECT_EQ(pose.yawspeed, -29);  // -0.5 rad/s = -28.6 deg/s
  EXPECT_EQ(converted.messages[0].time(), (protocol::Timestamp{6, 500000}));

  EXPECT_TRUE(carmen_to_player(CarmenParam{"robot_length", "0.5", {1, "h", 1}}).messages.empty());
  EXPECT_THROW(carmen_to_player(flaser(std::vector<double>(402, 1.0))), std::invalid_argument);
  EXPECT_THROW(carmen_to_player(flaser({1.0, 7000.0})), std::invalid_argument);
  EXPECT_THROW(carmen_to_player(flaser({1.0, -1.0})), std::invalid_argument);
  auto negative_time = flaser({1.0});
  negative_time.stamp.ipc_timestamp = -1;
  EXPECT_THROW(carmen_to_player(negative_time), std::invalid_argument);
}

TEST(PlayerToCarmen, PosesFollowingAScanJoinIt) {
  PlayerToCarmen converter;
  const auto odom = carmen_to_player(CarmenOdometry{{0.1, 0.2, 0}, 0.25, 0, 0, {3.0, "pippo", 4.0}});
  for (const auto& m : odom.messages) EXPECT_TRUE(converter.feed(m, odom.host));
  const auto scan = carmen_to_player(flaser(std::vector<double>(180, 1.5)));
  for (const auto& m : scan.messages) EXPECT_TRUE(converter.feed(m, scan.host));
  converter.finish();
  const auto records = converter.take_records();
  ASSERT_EQ(records.size(), 2u);  // the scan's position joins the FLASER, not a second ODOM
  const auto& odometry = std::get<CarmenOdometry>(records[0]);
  EXPECT_DOUBLE_EQ(odometry.pose.x, 0.1);
  EXPECT_DOUBLE_EQ(odometry.tv, 0.25);
  EXPECT_EQ(odometry.stamp, (CarmenStamp{3.0, "pippo", 4.0}));
  const auto& laser = std::get<CarmenLaser>(records[1]);
  EXPECT_EQ(laser.ranges, std::vector<double>(180, 1.5));
  EXPECT_NEAR(laser.robot_pose->theta, std::numbers::pi / 4, 0.5 * std::numbers::pi / 180);
  EXPECT_DOUBLE_EQ(laser.robot_pose->x, 1.0);
  EXPECT_DOUBLE_EQ(laser.laser_pose->x, 1.25);
  EXPECT_DOUBLE_EQ(laser.laser_pose->theta, std::numbers::pi / 2);
  EXPECT_EQ(laser.stamp, (CarmenStamp{1000.5, "pippo", 12.25}));
  EXPECT_EQ(converter.layout_mismatches(), 0u);
  EXPECT_EQ(converter.scans_without_pose(), 0u);
}

TEST(PlayerToCarmen, CountsLayoutsFlaserCannotHoldAndScansWithoutPose) {
  auto laser = flaser(std::vector<double>(180, 1.0));
  laser.config.start_angle = -std::numbers::pi / 4;  // not what FLASER readers guess
  laser.robot_pose.reset();
  laser.laser_pose.reset();
  PlayerToCarmen converter;
  EXPECT_TRUE(converter.feed(carmen_laser_to_player(laser, 0, {1, 0}, {1, 0}), "h"));
  EXPECT_FALSE(converter.feed(carmen_laser_to_player(laser, 1, {1, 0}, {1, 0}), "h"));  // laser:1
  converter.finish();
  EXPECT_EQ(converter.take_records().size(), 1u);
  EXPECT_EQ(converter.layout_mismatches(), 1u);
  EXPECT_EQ(converter.scans_without_pose(), 1u);
}

// Every scan of a real log survives CARMEN -> Player -> CARMEN, ranges to the
// millimetre (centimetre for scans with 81.83 m readings), poses to the
// millimetre and half a degree, times exactly as written.
TEST(LogConversionRadish, IntelRoundTripKeepsEveryScan) {
  const auto path = std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "radish" / "intel-corrected.log.gz";
  auto in = open_log_input(path);
  CarmenLogReader reader(*in, path.string(), {.strict = true});
  PlayerToCarmen converter;
  std::vector<CarmenRecord> originals;
  std::size_t scans = 0;
  std::size_t odometry = 0;
  std::size_t compared = 0;
  const double half_degree = 0.5 * std::numbers::pi / 180 + 1e-9;
  const auto check_pose = [&](const CarmenPose& a, const CarmenPose& b) {
    EXPECT_NEAR(a.x, b.x, 0.0005 + 1e-9);
    EXPECT_NEAR(a.y, b.y, 0.0005 + 1e-9);
    EXPECT_NEAR(std::remainder(a.theta - b.theta, 2 * std::numbers::pi), 0.0, half_degree);
  };
  const auto compare = [&] {
    auto back = converter.take_records();
    ASSERT_EQ(back.size(), originals.size());
    for (std::size_t i = 0; i < back.size(); ++i, ++compared) {
      ASSERT_EQ(back[i].index(), originals[i].index());
      if (const auto* scan = std::get_if<CarmenLaser>(&originals[i])) {
        const auto& again = std::get<CarmenLaser>(back[i]);
        ASSERT_EQ(again.ranges.size(), scan->ranges.size());
        for (std::size_t b = 0; b < scan->ranges.size(); ++b) EXPECT_NEAR(again.ranges[b], scan->ranges[b], 0.0051);
        check_pose(*again.robot_pose, *scan->robot_pose);
        check_pose(*again.laser_pose, *scan->laser_pose);
        EXPECT_NEAR(again.stamp.ipc_timestamp, scan->stamp.ipc_timestamp, 1e-6);
        EXPECT_NEAR(again.stamp.logger_timestamp, scan->stamp.logger_timestamp, 1e-6);
      } else {
        check_pose(std::get<CarmenOdometry>(back[i]).pose, std::get<CarmenOdometry>(originals[i]).pose);
      }
    }
    originals.clear();
  };
  while (auto record = reader.next()) {
    if (std::holds_alternative<CarmenParam>(*record)) continue;
    scans += std::holds_alternative<CarmenLaser>(*record) ? 1 : 0;
    odometry += std::holds_alternative<CarmenOdometry>(*record) ? 1 : 0;
    originals.push_back(*record);
    const auto converted = carmen_to_player(*record);
    for (const auto& message : converted.messages) converter.feed(message, converted.host);
    // A scan waits for its poses; an ODOM flushes everything before it.
    if (originals.size() > 64 && std::holds_alternative<CarmenOdometry>(*record)) compare();
  }
  converter.finish();
  compare();
  EXPECT_EQ(scans, 910u);
  EXPECT_EQ(odometry, 14541u);
  EXPECT_EQ(compared, 910u + 14541u);
  EXPECT_EQ(converter.layout_mismatches(), 0u);
}

}  // namespace log_conversion_test
}  // namespace playerkit::log
