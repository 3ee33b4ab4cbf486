#include "log/text_log_tokens.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace playerkit::log {
namespace text_log_tokens_test {

TEST(TextLogTokens, SplitsKeepingOffsets) {
  const std::string line = "1.5  localhost 6665\tposition 00 1.4 +01.250 -00.500 +1.571";
  const auto tokens = split_line_tokens(line);
  ASSERT_EQ(tokens.size(), 9u);
  EXPECT_EQ(tokens[kInterfaceColumn].text, "position");
  EXPECT_EQ(tokens[1].offset, 5u);
  EXPECT_EQ(line.substr(tokens[kFirstFieldColumn].offset, 7), "+01.250");
}

TEST(TextLogTokens, ReadsThePoseOfPositionAndBothTruthFormats) {
  const auto position = read_text_pose(split_line_tokens("1 h 6665 position 00 1 +01.250 -00.500 +1.571 0 0 0"), false);
  EXPECT_DOUBLE_EQ(position.x, 1.25);
  EXPECT_DOUBLE_EQ(position.y, -0.5);
  EXPECT_DOUBLE_EQ(position.yaw, 1.571);
  // 0.2.0's truth is x y z roll pitch yaw.
  const auto truth = read_text_pose(split_line_tokens("1 h 6665 truth 00 1 +2.000 +3.000 +0.000 +0.000 +0.000 -0.250"), true);
  EXPECT_DOUBLE_EQ(truth.x, 2.0);
  EXPECT_DOUBLE_EQ(truth.y, 3.0);
  EXPECT_DOUBLE_EQ(truth.yaw, -0.25);
}

TEST(TextLogTokens, ShortLinesAndWordsAreErrors) {
  EXPECT_THROW((void)read_text_pose(split_line_tokens("1 h 6665 position 00 1 +01.250"), false), std::runtime_error);
  EXPECT_THROW((void)read_text_pose(split_line_tokens("1 h 6665 position 00 1 a b c"), false), std::runtime_error);
}

TEST(TextLogTokens, ReplacesTokensKeepingEveryOtherByte) {
  const std::string line = "1.5  localhost 6665 position 00 1.4 +01.250 -00.500 +1.571 rest";
  const auto tokens = split_line_tokens(line);
  EXPECT_EQ(replace_tokens(line, tokens, kFirstFieldColumn, {"X", "Y", "W"}),
            "1.5  localhost 6665 position 00 1.4 X Y W rest");
}

}  // namespace text_log_tokens_test
}  // namespace playerkit::log
