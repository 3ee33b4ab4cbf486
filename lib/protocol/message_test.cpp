#include "protocol/message.hpp"

#include <gtest/gtest.h>

#include <limits>

#include "protocol/banner.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::protocol {
namespace message_test {

// wire-format.md §4, worked example: the SYNCH at 1086000000.250000 s.
const std::vector<std::uint8_t> kSynchBytes = {
    0x58, 0x78, 0x00, 0x05, 0x00, 0x01, 0x00, 0x00, 0x40, 0xBB, 0x0B, 0x80, 0x00,
    0x03, 0xD0, 0x90, 0x40, 0xBB, 0x0B, 0x80, 0x00, 0x03, 0xD0, 0x90, 0x00, 0x00,
    0x00, 0x00, 0x00, 0x00, 0x00, 0x00};

TEST(Message, SynchOfTheSpecExample) {
  const Timestamp now{1086000000, 250000};
  const auto header = make_header(MessageType::kSynch, {kPlayerCode, 0}, now, now);
  EXPECT_EQ(encode_message(header, {}), kSynchBytes);
  const auto parsed = parse_message(kSynchBytes);
  ASSERT_TRUE(parsed);
  EXPECT_EQ(parsed->consumed, 32u);
  EXPECT_EQ(parsed->message.type(), MessageType::kSynch);
  EXPECT_EQ(parsed->message.time(), now);
}

TEST(Message, ParseWaitsForWholeMessagesAndSplitsConcatenatedOnes) {
  Message power;
  power.header = make_header(MessageType::kData, {kPowerCode, 0}, {1, 2}, {3, 4});
  power.payload = {0x00, 0x7B};
  auto stream = encode_message(power);
  EXPECT_FALSE(parse_message(std::span(stream).first(31)));
  EXPECT_FALSE(parse_message(std::span(stream).first(33)));
  stream.insert(stream.end(), kSynchBytes.begin(), kSynchBytes.end());
  const auto first = parse_message(stream);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->consumed, 34u);
  EXPECT_EQ(first->message.payload, power.payload);
  EXPECT_EQ(first->message.header.size, 2u);
  const auto second = parse_message(std::span(stream).subspan(first->consumed));
  ASSERT_TRUE(second);
  EXPECT_EQ(second->message.type(), MessageType::kSynch);
}

TEST(Message, BadStxAndOversizeAreErrors) {
  auto bytes = kSynchBytes;
  bytes[1] = 0x79;
  EXPECT_THROW(parse_message(bytes), DecodeError);
  bytes = kSynchBytes;
  bytes[28] = 0x00;
  bytes[29] = 0x00;
  bytes[30] = 0x1F;
  bytes[31] = 0xE1;  // 8161 bytes: one more than the limit
  try {
    parse_message(bytes);
    FAIL();
  } catch (const DecodeError& e) {
    EXPECT_EQ(e.field_name(), "size");
    EXPECT_EQ(e.got(), 8161u);
  }
}

TEST(Message, TimestampFromSecondsRoundsToMicroseconds) {
  EXPECT_EQ(Timestamp::from_seconds(1086000000.25), (Timestamp{1086000000, 250000}));
  EXPECT_EQ(Timestamp::from_seconds(1.9999996), (Timestamp{2, 0}));
  EXPECT_EQ(Timestamp::from_seconds(-1), (Timestamp{0, 0}));
  EXPECT_EQ(Timestamp::from_seconds(4294967295.25), (Timestamp{4294967295, 250000}));
}

TEST(Message, TimestampFromSecondsStopsAtTheLatestHeaderTime) {
  // A header with usec over a million reads as past 2^32 s (fuzz finding).
  const double past = (Timestamp{0xFFFFFFFF, 0xFFFFFFFF}).seconds();
  EXPECT_EQ(Timestamp::from_seconds(past), (Timestamp{0xFFFFFFFF, 999999}));
  EXPECT_EQ(Timestamp::from_seconds(4294967295.9999999), (Timestamp{0xFFFFFFFF, 999999}));
  EXPECT_EQ(Timestamp::from_seconds(1e300), (Timestamp{0xFFFFFFFF, 999999}));
  EXPECT_EQ(Timestamp::from_seconds(std::numeric_limits<double>::infinity()), (Timestamp{0xFFFFFFFF, 999999}));
  EXPECT_EQ(Timestamp::from_seconds(std::numeric_limits<double>::quiet_NaN()), (Timestamp{0, 0}));
  EXPECT_DOUBLE_EQ((Timestamp{12, 500000}).seconds(), 12.5);
}

TEST(Banner, IsPlayerVersionPaddedTo32Bytes) {
  const Banner banner = make_banner();
  std::array<std::uint8_t, 32> expected{};
  const std::string text = "Player v.1.5";
  std::copy(text.begin(), text.end(), expected.begin());
  EXPECT_EQ(banner, expected);
  EXPECT_EQ(parse_banner(banner), "1.5");
  EXPECT_EQ(parse_banner(make_banner("1.5 (stage)")), "1.5 (stage)");
}

TEST(Banner, RejectsOtherBytes) {
  auto banner = make_banner();
  banner[0] = 'p';
  EXPECT_FALSE(parse_banner(banner));
  banner = make_banner();
  banner[31] = 'x';  // garbage after the NUL
  EXPECT_FALSE(parse_banner(banner));
  EXPECT_FALSE(parse_banner(std::span(banner).first(31)));
  EXPECT_THROW(make_banner(std::string(23, '9')), std::length_error);
}

}  // namespace message_test
}  // namespace playerkit::protocol
