#include "families/ptu46/protocol/ptu_line_format.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::ptu46 {
namespace {

TEST(PtuLineFormat, ReadsAReplyBehindItsEcho) {
  const auto value = parse_reply_after_echo("pr * 185.1428");
  ASSERT_TRUE(value);
  EXPECT_DOUBLE_EQ(*value->number, 185.1428);
  const auto refused = parse_reply_after_echo("pp9999 ! Maximum allowable Pan position is 3090");
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->kind, Reply::Kind::refused);
  EXPECT_EQ(parse_reply_after_echo("r !T!T!P!P*")->kind, Reply::Kind::reset);
  EXPECT_EQ(parse_reply_after_echo("* 5")->kind, Reply::Kind::value);  // no echo at all
}

TEST(PtuLineFormat, ReadsAReplyBehindNoise) {
  EXPECT_EQ(parse_reply_after_echo("\x13\xf0" "ed*")->kind, Reply::Kind::done);
  EXPECT_DOUBLE_EQ(*parse_reply_after_echo("q\x02" "* 583")->number, 583);
}

TEST(PtuLineFormat, AnEchoAloneIsNoReply) {
  EXPECT_EQ(parse_reply_after_echo("pr"), std::nullopt);
  EXPECT_EQ(parse_reply_after_echo("pp583"), std::nullopt);
}

TEST(PtuLineFormat, CutsAtCrLfOrEitherAlone) {
  const framing::TerminatedLineFormat format(reply_line_options());
  for (const std::string line : {"* 5\r\n", "* 5\n", "* 5\r"}) {
    const std::span bytes(reinterpret_cast<const std::uint8_t*>(line.data()), line.size());
    // A lone CR may still be followed by its LF: the format may wait for one more byte.
    auto scan = format.scan(bytes);
    if (scan.kind == framing::FrameScan::Kind::need_more) {
      const std::string more = line + "*";
      scan = format.scan(std::span(reinterpret_cast<const std::uint8_t*>(more.data()), more.size()));
    }
    ASSERT_EQ(scan.kind, framing::FrameScan::Kind::frame) << line;
    EXPECT_EQ(scan.length, line.size());
  }
}

}  // namespace
}  // namespace playerkit::hardware::ptu46
