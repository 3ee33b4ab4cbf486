// Golden frames from segwayrmp.md §2.2's worked examples, and the status
// messages' slots (§2.1) read back.
#include "families/segwayrmp/protocol/rmp_frames.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "families/segwayrmp/protocol/rmp_odometry.hpp"

namespace playerkit::hardware::segwayrmp {
namespace {

std::vector<std::uint8_t> data_of(const framing::CanFrame& frame) {
  return {frame.data.begin(), frame.data.begin() + frame.dlc};
}

TEST(RmpFrames, VelocityCommandsAreTheSheetsWorkedExamples) {
  const auto forward = command_frame({.trans = trans_counts(500), .rot = rot_counts(10)});
  EXPECT_EQ(forward.id, 0x413u);
  EXPECT_FALSE(forward.extended);
  EXPECT_EQ(data_of(forward), (std::vector<std::uint8_t>{0x00, 0xA4, 0x00, 0x4E, 0, 0, 0, 0}));
  const auto back = command_frame({.trans = trans_counts(-300), .rot = rot_counts(-20)});
  EXPECT_EQ(data_of(back), (std::vector<std::uint8_t>{0xFF, 0x9D, 0xFF, 0x64, 0, 0, 0, 0}));
}

TEST(RmpFrames, ResetAllIntegratorsWhileStoppedIsTheSheetsExample) {
  const auto frame = command_frame({.status = StatusCommand::reset_integrators, .status_value = kResetAll});
  EXPECT_EQ(data_of(frame), (std::vector<std::uint8_t>{0, 0, 0, 0, 0x00, 0x32, 0x0F, 0x0F}));
  EXPECT_EQ(parse_command(frame), (Command{.status = StatusCommand::reset_integrators, .status_value = 0x0F}));
}

TEST(RmpFrames, ShutdownIsAllZeroOn0x412) {
  const auto frame = shutdown_frame();
  EXPECT_EQ(frame.id, 0x412u);
  EXPECT_EQ(data_of(frame), std::vector<std::uint8_t>(8, 0));
  EXPECT_FALSE(parse_command(frame).has_value());
}

TEST(RmpFrames, CountsAreClampedToWhatTheRobotTakes) {
  EXPECT_EQ(trans_counts(3576), 1176);
  EXPECT_EQ(trans_counts(10000), 1176);
  EXPECT_EQ(trans_counts(-10000), -1176);
  EXPECT_EQ(rot_counts(1000), 1024);
  EXPECT_EQ(rot_counts(-1000), -1024);
}

TEST(RmpFrames, StatusMessagesRoundTripThroughTheAssembler) {
  const Status status{.battery = 100,
                      .pitch = -78,
                      .pitch_rate = 15,
                      .roll = 39,
                      .roll_rate = -4,
                      .left_wheel_velocity = 166,
                      .right_wheel_velocity = 170,
                      .yaw_rate = -78,
                      .frame_counter = 0xBEEF,
                      .left_wheel_displacement = 0x12345678,
                      .right_wheel_displacement = 0xFFFF0001,
                      .fore_aft_displacement = 0x00010002,
                      .yaw_displacement = 0x80000000};
  const auto frames = status_frames(status);
  // 32-bit values: low half in the first slot, each slot big-endian.
  EXPECT_EQ(data_of(frames[4]), (std::vector<std::uint8_t>{0x00, 0x02, 0x00, 0x01, 0x00, 0x00, 0x80, 0x00}));
  EXPECT_EQ(data_of(frames[0]), (std::vector<std::uint8_t>{0, 0, 0, 0, 0x00, 0x64, 0, 0}));
  StatusAssembler assembler;
  for (std::size_t index = 0; index + 1 < frames.size(); ++index) EXPECT_FALSE(assembler.add(frames[index]));
  EXPECT_TRUE(assembler.add(frames[4]));
  EXPECT_EQ(assembler.status(), status);
}

TEST(RmpFrames, ASetIsCompleteOnlyWithEachOfTheFiveIds) {
  const auto frames = status_frames({});
  StatusAssembler assembler;
  EXPECT_FALSE(assembler.add(frames[0]));
  EXPECT_FALSE(assembler.add(frames[0]));
  framing::CanFrame other = frames[1];
  other.id = 0x405;
  EXPECT_FALSE(assembler.add(other));
  EXPECT_FALSE(assembler.add(frames[1]));
  EXPECT_FALSE(assembler.add(frames[2]));
  EXPECT_FALSE(assembler.add(frames[3]));
  EXPECT_TRUE(assembler.add(frames[4]));
  EXPECT_FALSE(assembler.add(frames[4]));  // a new set begins
}

TEST(RmpOdometry, FirstCountersAreTheOriginThenDistanceAndTurnAccumulate) {
  RmpOdometry odometry;
  EXPECT_EQ(odometry.update(1000, 5000).x, 0.0);
  const auto& moved = odometry.update(1000 + 33215, 5000);
  EXPECT_NEAR(moved.x, 1.0, 1e-9);
  // A quarter turn counter-clockwise, then a metre along +y.
  odometry.update(1000 + 33215, 5000 + 112644 / 4);
  const auto& turned = odometry.update(1000 + 2 * 33215, 5000 + 112644 / 4);
  EXPECT_NEAR(turned.x, 1.0, 1e-4);
  EXPECT_NEAR(turned.y, 1.0, 1e-9);
  EXPECT_NEAR(turned.theta, 1.5707963, 1e-4);
}

TEST(RmpOdometry, CountersWrapTheShortWayAndHeadingStaysInZeroToTwoPi) {
  RmpOdometry odometry;
  odometry.update(0xFFFFFF00u, 10);
  const auto& pose = odometry.update(0x00000100u, 0xFFFFFFF0u);  // +512 counts, -26 counts
  EXPECT_NEAR(pose.x, 512 / 33215.0, 1e-9);
  EXPECT_GT(pose.theta, 6.0);
  EXPECT_LT(pose.theta, 6.2832);
  odometry.reset();
  EXPECT_EQ(odometry.pose().theta, 0.0);
  EXPECT_EQ(odometry.update(7, 7).x, 0.0);
}

}  // namespace
}  // namespace playerkit::hardware::segwayrmp
