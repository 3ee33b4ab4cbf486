#include "families/ptu46/protocol/ptu_replies.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::ptu46 {
namespace {

TEST(PtuReplies, TerseValuesAsTheManualPrintsThem) {
  const auto resolution = parse_reply("* 185.1428");
  ASSERT_TRUE(resolution);
  EXPECT_EQ(resolution->kind, Reply::Kind::value);
  EXPECT_DOUBLE_EQ(*resolution->number, 185.1428);
  const auto position = parse_reply("* -907");
  ASSERT_TRUE(position);
  EXPECT_DOUBLE_EQ(*position->number, -907);
}

TEST(PtuReplies, VerboseValuesEndInTheirNumber) {
  const auto reply = parse_reply("* Current Pan position is 583");
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->kind, Reply::Kind::value);
  EXPECT_DOUBLE_EQ(*reply->number, 583);
}

TEST(PtuReplies, DoneRefusedAndReset) {
  const auto done = parse_reply("*");
  ASSERT_TRUE(done);
  EXPECT_EQ(done->kind, Reply::Kind::done);
  EXPECT_TRUE(done->ok());
  const auto refused = parse_reply("! Maximum allowable Pan position is 3090");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->kind, Reply::Kind::refused);
  EXPECT_FALSE(refused->ok());
  EXPECT_EQ(refused->text, "Maximum allowable Pan position is 3090");
  const auto reset = parse_reply("!T!T!P!P*");
  ASSERT_TRUE(reset);
  EXPECT_EQ(reset->kind, Reply::Kind::reset);
  EXPECT_TRUE(reset->ok());
}

TEST(PtuReplies, LinesThatAreNoReply) {
  EXPECT_EQ(parse_reply(""), std::nullopt);
  EXPECT_EQ(parse_reply("pp583"), std::nullopt);  // an echo, not an answer
  EXPECT_EQ(parse_reply(" * 5"), std::nullopt);
}

TEST(PtuReplies, LinesTheUnitWritesParseBack) {
  EXPECT_EQ(value_line(583), "* 583");
  EXPECT_EQ(value_line(-3090), "* -3090");
  EXPECT_EQ(value_line(185.1428), "* 185.1428");
  EXPECT_EQ(done_line(), "*");
  EXPECT_EQ(refusal_line("Illegal command"), "! Illegal command");
  for (const double n : {-3090.0, 0.0, 583.0, 185.1428}) {
    const auto reply = parse_reply(value_line(n));
    ASSERT_TRUE(reply);
    EXPECT_DOUBLE_EQ(*reply->number, n);
  }
  EXPECT_EQ(parse_reply(reset_line())->kind, Reply::Kind::reset);
}

}  // namespace
}  // namespace playerkit::hardware::ptu46
