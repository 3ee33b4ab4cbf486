#include "emulators/mobile_base/robot_options.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <stdexcept>
#include <string>

#include "emulators/emulator_option_reader.hpp"

namespace playerkit::emulators::mobile_base {
namespace robot_options_test {

EmulatorKind robot_kind() {
  EmulatorKind kind;
  kind.name = "testbot";
  kind.options = robot_option_docs();
  return kind;
}

TEST(RobotOptions, DefaultsAreAPerfectRobotAtTheOrigin) {
  const EmulatorKind kind = robot_kind();
  const EmulatorOptionValues none;
  const RobotBodyOptions body = read_robot_options(EmulatorOptionReader(kind, none));
  EXPECT_EQ(body.initial_pose.x, 0.0);
  EXPECT_EQ(body.initial_pose.yaw, 0.0);
  EXPECT_EQ(body.odometry_error.translation_scale, 0.0);
  EXPECT_EQ(body.odometry_error.heading_drift_per_metre, 0.0);
  EXPECT_EQ(body.odometry_error.seed, 1u);
}

TEST(RobotOptions, ReadsPoseAndErrorInTheirUnits) {
  const EmulatorKind kind = robot_kind();
  const EmulatorOptionValues values{{"pose", "1,2,90"}, {"odometry_scale", "0.02"}, {"rotation_scale", "-0.01"},
                                    {"drift", "1.5"}, {"seed", "7"}};
  const RobotBodyOptions body = read_robot_options(EmulatorOptionReader(kind, values));
  EXPECT_DOUBLE_EQ(body.initial_pose.x, 1.0);
  EXPECT_DOUBLE_EQ(body.initial_pose.y, 2.0);
  EXPECT_NEAR(body.initial_pose.yaw, std::numbers::pi / 2, 1e-12);
  EXPECT_DOUBLE_EQ(body.odometry_error.translation_scale, 0.02);
  EXPECT_DOUBLE_EQ(body.odometry_error.rotation_scale, -0.01);
  EXPECT_NEAR(body.odometry_error.heading_drift_per_metre, 1.5 * std::numbers::pi / 180.0, 1e-12);
  EXPECT_EQ(body.odometry_error.seed, 7u);
}

TEST(RobotOptions, AValueOutOfRangeNamesTheKindAndTheOption) {
  const EmulatorKind kind = robot_kind();
  const EmulatorOptionValues values{{"odometry_scale", "2"}};
  try {
    (void)read_robot_options(EmulatorOptionReader(kind, values));
    FAIL() << "accepted a scale error of 200 %";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("testbot: odometry_scale=2"), std::string::npos) << e.what();
  }
}

}  // namespace robot_options_test
}  // namespace playerkit::emulators::mobile_base
