#include "families/p2os/driver/robot_readings.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "families/p2os/driver/robot_geometry.hpp"
#include "families/p2os/protocol/frame.hpp"
#include "protocol/binary_codec.hpp"

namespace playerkit::drivers::p2os {
namespace robot_readings_test {

namespace hw = hardware::p2os;

const hw::RobotParams& p3dx() { return *hw::find_robot_params("Pioneer", "p3dx"); }

// The sheet's worked SIP (§2.3): stopped, x = 100, theta = 1024 (90 deg),
// battery 12.0 V, compass byte 46 (90 deg), sonar #0 = 500 and #1 = 1000,
// TIMER 0x0105 (gripper state 1, analog port 5).
hw::StandardSip sheet_sip() {
  const std::vector<std::uint8_t> frame{0xFA, 0xFB, 0x21, 0x32, 0x64, 0x00, 0x00, 0x00, 0x00, 0x04, 0x00, 0x00,
                                        0x00, 0x00, 0x78, 0x00, 0x00, 0x00, 0x00, 0x01, 0x00, 0x2E, 0x02, 0x00,
                                        0xF4, 0x01, 0x01, 0xE8, 0x03, 0x05, 0x01, 0x00, 0x00, 0x00, 0x54, 0xD7};
  return hw::decode_sip(hw::frame_payload(frame));
}

TEST(RobotReadings, TheSheetsSipAsEachDeviceShowsIt) {
  RobotReadings readings(p3dx());
  readings.take_sip(sheet_sip());

  const protocol::SonarData sonar = readings.sonar();
  EXPECT_EQ(sonar.range_count, 16);  // the row's SonarNum, not the readings in this SIP
  EXPECT_EQ(sonar.ranges[0], 500);
  EXPECT_EQ(sonar.ranges[1], 1000);
  EXPECT_EQ(sonar.ranges[2], 0);
  EXPECT_EQ(readings.power().charge, 120);
  EXPECT_EQ(readings.compass().yaw, 90);
  EXPECT_EQ(readings.gripper().state, 0x01);
  EXPECT_EQ(readings.gripper().beams, 0x00);
  EXPECT_EQ(readings.aio().count, 1);
  EXPECT_EQ(readings.dio().count, 8);

  const protocol::PositionData position = readings.position({0.0, 0.0, 1024 * 0.001534});
  EXPECT_EQ(position.yaw, 90);
  EXPECT_EQ(position.xspeed, 0);
  EXPECT_EQ(position.stall, 0);
}

TEST(RobotReadings, SonarRangesConvertAndPersistUntilOverwritten) {
  const hw::RobotParams& p2dx = *hw::find_robot_params("Pioneer", "p2dx");  // 0.268 mm per unit
  RobotReadings readings(p2dx);
  hw::StandardSip sip;
  sip.sonar = {{3, 1000}, {15, 2000}, {16, 500}, {200, 500}};  // the last two are not transducers of a p2dx
  readings.take_sip(sip);
  sip.sonar = {{4, 10}};
  readings.take_sip(sip);
  const protocol::SonarData sonar = readings.sonar();
  EXPECT_EQ(sonar.ranges[3], 268);
  EXPECT_EQ(sonar.ranges[15], 536);
  EXPECT_EQ(sonar.ranges[4], 3);
  EXPECT_EQ(sonar.ranges[16], 0);
  EXPECT_EQ(readings.sonar_out_of_range(), 2u);
}

TEST(RobotReadings, SpeedsFromTheWheels) {
  RobotReadings readings(p3dx());
  hw::StandardSip sip;
  sip.left_velocity = 237;
  sip.right_velocity = 362;
  sip.stall_bumpers_high = 0x01;  // right wheel stalled
  readings.take_sip(sip);
  const protocol::PositionData position = readings.position({});
  EXPECT_EQ(position.xspeed, 299);  // (237 + 362) / 2, truncated as 1.5
  // (362 - 237) × 0.0056 / 2 rad/s = 20.05 deg/s, truncated.
  EXPECT_EQ(position.yawspeed, 20);
  EXPECT_EQ(position.stall, 1);
  EXPECT_EQ(position.yspeed, 0);
}

TEST(RobotReadings, ReportedYawIsWholeDegreesFrom0To359) {
  EXPECT_EQ(whole_degrees(0.0), 0);
  EXPECT_EQ(whole_degrees(4095 * 0.001534), 0);  // 1.5 said 360
  EXPECT_EQ(whole_degrees(-0.5 * 3.14159265358979), 270);
}

TEST(RobotReadings, BumpersAreFiveFrontThenFiveRearSwitchesHighestBitFirst) {
  RobotReadings readings(p3dx());
  hw::StandardSip sip;
  sip.stall_bumpers_high = hw::stall_bumper_byte(false, 0b00001);  // front switch 1 (SIP bit 1)
  sip.stall_bumpers_low = hw::stall_bumper_byte(true, 0b10000);    // rear switch 5 (SIP bit 5), stalled
  readings.take_sip(sip);
  const protocol::BumperData bumper = readings.bumper();
  EXPECT_EQ(bumper.bumper_count, 10);
  const std::vector<std::uint8_t> pressed(bumper.bumpers.begin(), bumper.bumpers.begin() + 10);
  EXPECT_EQ(pressed, (std::vector<std::uint8_t>{0, 0, 0, 0, 1, 1, 0, 0, 0, 0}));
}

TEST(RobotReadings, CompassKeepsItsLastHeadingOverNoReadingBytes) {
  RobotReadings readings(p3dx());
  hw::StandardSip sip;
  sip.compass = 46;
  readings.take_sip(sip);
  for (const int none : {0, 181, 255}) {
    sip.compass = static_cast<std::uint8_t>(none);
    readings.take_sip(sip);
    EXPECT_EQ(readings.compass().yaw, 90) << none;
  }
  sip.compass = 1;
  readings.take_sip(sip);
  EXPECT_EQ(readings.compass().yaw, 0);
}

TEST(RobotReadings, AnalogInputIsAPlainBigEndianNumber) {
  RobotReadings readings(p3dx());
  hw::StandardSip sip;
  sip.analog = 200;
  readings.take_sip(sip);
  const auto bytes = protocol::encode(readings.aio());
  // count, then anin[0] as a big-endian int32 (1.5 left it in host order).
  EXPECT_EQ((std::vector<std::uint8_t>(bytes.begin(), bytes.begin() + 5)),
            (std::vector<std::uint8_t>{1, 0, 0, 0, 200}));
}

TEST(RobotReadings, GyroIsTheAveragedRawRate) {
  RobotReadings readings(p3dx());
  EXPECT_EQ(readings.gyro().yawspeed, 0);
  readings.take_gyro(hw::GyroPacket{{{500, 25}, {503, 25}}});
  EXPECT_EQ(readings.gyro().yawspeed, 502);  // 501.5 rounded
}

TEST(RobotReadings, TheBlobfinderIsTheWholeStructWithOneBlob) {
  RobotReadings readings(p3dx());
  readings.take_cmucam(hw::CmucamColor{200, 100, 50, 1, 1, 1});
  readings.take_cmucam(hw::CmucamTracking{40, 70, 30, 60, 49, 79, 100, 128});
  const protocol::BlobfinderData data = readings.blobfinder();
  EXPECT_EQ(protocol::encode(data).size(), 7172u);
  EXPECT_EQ(data.width, 80);
  EXPECT_EQ(data.height, 143);
  EXPECT_EQ(data.header[0].num, 1);
  const protocol::BlobfinderBlob& blob = data.blobs[0];
  EXPECT_EQ(blob.color, 0x00C86432u);
  EXPECT_EQ(blob.area, 20u * 20u * 128u / 255u);
  EXPECT_EQ(blob.x, 40);
  EXPECT_EQ(blob.y, 70);
  EXPECT_EQ(blob.left, 30);
  EXPECT_EQ(blob.right, 49);
  EXPECT_EQ(blob.top, 60);
  EXPECT_EQ(blob.bottom, 79);
  EXPECT_EQ(blob.range, 128);
  // No blob in view: nothing counted on the channel.
  readings.take_cmucam(hw::CmucamTracking{});
  EXPECT_EQ(readings.blobfinder().header[0].num, 0);
}

TEST(RobotGeometry, SonarPosesOfTheRowThenZeros) {
  const protocol::SonarGeom p3dx_geometry = sonar_geometry(p3dx());
  EXPECT_EQ(p3dx_geometry.subtype, 1);
  EXPECT_EQ(p3dx_geometry.pose_count, 16);
  EXPECT_EQ(p3dx_geometry.poses[0], (std::array<std::int16_t, 3>{115, 130, 90}));
  EXPECT_EQ(p3dx_geometry.poses[11], (std::array<std::int16_t, 3>{-210, -25, -170}));
  for (std::size_t i = 16; i < 64; ++i) EXPECT_EQ(p3dx_geometry.poses[i], (std::array<std::int16_t, 3>{})) << i;

  const protocol::SonarGeom amigo = sonar_geometry(*hw::find_robot_params("Pioneer", "amigo"));
  EXPECT_EQ(amigo.pose_count, 8);
  EXPECT_EQ(amigo.poses[7], (std::array<std::int16_t, 3>{-146, 60, 145}));
  EXPECT_EQ(amigo.poses[8], (std::array<std::int16_t, 3>{}));

  const protocol::SonarGeom perfpb = sonar_geometry(*hw::find_robot_params("Pioneer", "perfpb"));
  EXPECT_EQ(perfpb.pose_count, 32);
  EXPECT_EQ(perfpb.poses[24], (std::array<std::int16_t, 3>{-195, -130, -90}));
  EXPECT_EQ(protocol::encode(perfpb).size(), 387u);
}

TEST(RobotGeometry, PositionGeometryIsThe15OneForEveryRobot) {
  const protocol::PositionGeom geometry = position_geometry();
  EXPECT_EQ(geometry.subtype, 1);
  EXPECT_EQ(geometry.pose, (std::array<std::int16_t, 3>{-100, 0, 0}));
  EXPECT_EQ(geometry.size, (std::array<std::uint16_t, 2>{500, 450}));
}

}  // namespace robot_readings_test
}  // namespace playerkit::drivers::p2os
