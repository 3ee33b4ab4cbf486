#include "families/p2os/driver/cmucam_commands.hpp"

#include <gtest/gtest.h>

namespace playerkit::drivers::p2os {
namespace cmucam_commands_test {

namespace hw = hardware::p2os;

TEST(CmucamCommands, SetColorTracksTheRangeOrAnythingWhenABoundIsNegative) {
  protocol::BlobfinderColorConfig color{1, 100, 200, 10, 20, 0, 255};
  EXPECT_EQ(tracking_text(color), "TC 100 200 10 20 0 255\r");
  color.gmax = -1;
  EXPECT_EQ(tracking_text(color), "TW\r");
}

TEST(CmucamCommands, ImagerParametersOnlyForTheFieldsGiven) {
  protocol::BlobfinderImagerConfig imager{2, 100, -1, -1, -1};
  EXPECT_EQ(imager_text(imager), "CR  6 100\r");
  imager = {2, 10, 20, 3, 1};
  EXPECT_EQ(imager_text(imager), "CR  6 10 5 20 19 33 18 36\r");
  imager = {2, -1, -1, -1, 0};
  EXPECT_EQ(imager_text(imager), "CR  19 32\r");
  imager = {2, -1, -1, 7, -1};  // no such colour mode
  EXPECT_EQ(imager_text(imager), std::nullopt);
}

TEST(CmucamCommands, ResetTrackAndPollAreTextsAndAux2Reads) {
  const auto reset = cmucam_reset_commands();
  ASSERT_EQ(reset.size(), 4u);
  EXPECT_EQ(reset[0], hw::Command::with_string(hw::command::tty3, "\r"));
  EXPECT_EQ(reset[1], hw::Command::with_string(hw::command::tty3, "RS\r"));
  EXPECT_EQ(reset[2], hw::Command::with_string(hw::command::tty3, "RM 3\r"));
  EXPECT_EQ(reset[3], hw::Command::with_integer(hw::command::getaux2, 0));
  const auto track = cmucam_track_commands(kTrackCurrentColor);
  ASSERT_EQ(track.size(), 3u);
  EXPECT_EQ(track[1], hw::Command::with_string(hw::command::tty3, "TC\r"));
  EXPECT_EQ(track[2], hw::Command::with_integer(hw::command::getaux2, 19));
  EXPECT_EQ(cmucam_poll_commands(),
            (std::vector<hw::Command>{hw::Command::with_integer(hw::command::getaux2, 0),
                                      hw::Command::with_integer(hw::command::getaux2, 19)}));
}

}  // namespace cmucam_commands_test
}  // namespace playerkit::drivers::p2os
