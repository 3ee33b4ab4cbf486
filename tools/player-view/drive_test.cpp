#include "drive.hpp"

#include <gtest/gtest.h>

namespace playerkit::player_view {
namespace drive_test {

constexpr std::string_view kForward = R"({"type":"drive","x":1,"yaw":0})";
constexpr std::string_view kLeft = R"({"type":"drive","x":0,"yaw":1})";
constexpr std::string_view kStop = R"({"type":"stop"})";

TEST(DriveControl, KeysBecomeVelocitiesAndAStopStops) {
  DriveControl drive(0.3, 0.5);
  EXPECT_FALSE(drive.update(0.0));
  drive.message(1, kForward, 0.0);
  EXPECT_TRUE(drive.starting());
  EXPECT_EQ(drive.update(0.0), (DriveCommand{0.3, 0.0}));
  EXPECT_FALSE(drive.starting());
  EXPECT_FALSE(drive.update(0.1));  // unchanged: nothing to send
  drive.message(1, kLeft, 0.2);
  EXPECT_EQ(drive.update(0.2), (DriveCommand{0.0, 0.5}));
  drive.message(1, kStop, 0.3);
  EXPECT_EQ(drive.update(0.3), DriveCommand{});
}

TEST(DriveControl, ThePageClosingStopsTheRobot) {
  DriveControl drive(0.3, 0.5);
  drive.message(7, kForward, 0.0);
  ASSERT_TRUE(drive.update(0.0));
  drive.closed(8);  // another page
  EXPECT_FALSE(drive.update(0.1));
  drive.closed(7);
  EXPECT_EQ(drive.update(0.1), DriveCommand{});
}

TEST(DriveControl, ASilentPageStopsTheRobot) {
  DriveControl drive(0.3, 0.5, 0.6);
  drive.message(1, kForward, 0.0);
  ASSERT_TRUE(drive.update(0.0));
  drive.message(1, kForward, 0.5);  // renewed
  EXPECT_FALSE(drive.update(1.0));
  EXPECT_EQ(drive.update(1.2), DriveCommand{});
}

TEST(DriveControl, TheNewestPageDrivesAndAnyPageMayStop) {
  DriveControl drive(0.3, 0.5);
  drive.message(1, kForward, 0.0);
  drive.message(2, kLeft, 0.1);
  EXPECT_EQ(drive.update(0.1), (DriveCommand{0.0, 0.5}));
  drive.closed(1);  // no longer driving: nothing changes
  EXPECT_FALSE(drive.update(0.2));
  drive.message(3, kStop, 0.3);
  EXPECT_EQ(drive.update(0.3), DriveCommand{});
}

TEST(DriveControl, MotorButtonsAskForPowerAndOffStops) {
  DriveControl drive(0.3, 0.5);
  EXPECT_FALSE(drive.take_motor_request());
  drive.message(1, R"({"type":"motors","on":true})", 0.0);
  EXPECT_EQ(drive.take_motor_request(), true);
  EXPECT_FALSE(drive.take_motor_request());
  drive.message(1, kForward, 0.1);
  ASSERT_TRUE(drive.update(0.1));
  drive.message(2, R"({"type":"motors","on":false})", 0.2);
  EXPECT_EQ(drive.take_motor_request(), false);
  EXPECT_EQ(drive.update(0.2), DriveCommand{});
  drive.message(1, R"({"type":"motors","on":"yes"})", 0.3);
  EXPECT_FALSE(drive.take_motor_request());
}

TEST(DriveControl, OddMessagesAreIgnoredAndSpeedsClamped) {
  DriveControl drive(0.3, 0.5);
  drive.message(1, "not json", 0.0);
  drive.message(1, R"({"type":"goal"})", 0.0);
  drive.message(1, R"([1,2])", 0.0);
  EXPECT_FALSE(drive.update(0.0));
  drive.message(1, R"({"type":"drive","x":-5,"yaw":"left"})", 0.0);
  EXPECT_EQ(drive.update(0.0), (DriveCommand{-0.3, 0.0}));
}

}  // namespace drive_test
}  // namespace playerkit::player_view
