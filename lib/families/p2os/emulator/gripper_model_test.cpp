#include "families/p2os/emulator/gripper_model.hpp"

#include "families/p2os/protocol/gripper.hpp"

#include <gtest/gtest.h>

namespace playerkit::emulators::p2os {
namespace gripper_model_test {

namespace state = hardware::p2os::gripper_state;
namespace cmd = hardware::p2os::gripper_command;

TEST(GripperModel, StartsStoredAndIgnoresCommandsToWhereItIs) {
  GripperModel gripper(1.0);
  EXPECT_EQ(gripper.state_bits(), state::paddles_closed | state::lift_up);
  gripper.command(cmd::close);
  gripper.command(cmd::lift_up);
  EXPECT_FALSE(gripper.moving());
}

TEST(GripperModel, TravelTakesTheConfiguredTime) {
  GripperModel gripper(2.0);
  gripper.command(cmd::open);
  gripper.run(1.0);
  EXPECT_NEAR(gripper.paddle_opening(), 0.5, 1e-12);
  EXPECT_EQ(gripper.state_bits(), state::paddles_moving | state::lift_up);
  gripper.run(1.5);
  EXPECT_EQ(gripper.paddle_opening(), 1.0);
  EXPECT_EQ(gripper.state_bits(), state::paddles_open | state::lift_up);
}

TEST(GripperModel, HaltStopsBothAndUnknownCommandsAreIgnored) {
  GripperModel gripper(1.0);
  gripper.command(cmd::deploy);
  gripper.run(0.25);
  gripper.command(99);
  EXPECT_TRUE(gripper.moving());
  gripper.command(cmd::halt);
  gripper.run(1.0);
  EXPECT_NEAR(gripper.paddle_opening(), 0.25, 1e-12);
  EXPECT_NEAR(gripper.lift_height(), 0.75, 1e-12);
  EXPECT_EQ(gripper.state_bits(), 0);
}

}  // namespace gripper_model_test
}  // namespace playerkit::emulators::p2os
