#include "families/sick/protocol/replies.hpp"

#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::sick {
namespace replies_test {

using testing::bytes;

ConfigBlock numbered_block() {
  ConfigBlock block;
  for (std::size_t i = 0; i < kConfigBlockSize; ++i) block.bytes[i] = static_cast<std::uint8_t>(i + 1);
  return block;
}

TEST(SickReplies, ModeReplyIsTheSheetsOk) {
  EXPECT_EQ(encode_reply(ModeReply{}), bytes("02 80 03 00 A0 00 10 16 0A"));
  EXPECT_EQ(parse_mode_reply(unframe_reply(bytes("02 80 03 00 A0 00 10 16 0A"))), ModeReply{});
  const auto refused = encode_reply(ModeReply{ModeResult::wrong_password});
  EXPECT_EQ(unframe_reply(refused), (Reply{0xA0, {0x01}, 0x10}));
  EXPECT_EQ(parse_mode_reply(unframe_reply(refused)).result, ModeResult::wrong_password);
}

TEST(SickReplies, NotAcknowledgedIsTheSheets92) {
  EXPECT_EQ(encode_reply(NotAcknowledgedReply{}), bytes("02 80 03 00 92 00 10 DE 6E"));
  EXPECT_EQ(parse_not_acknowledged(unframe_reply(bytes("02 80 03 00 92 00 10 DE 6E"))),
            NotAcknowledgedReply{});
  EXPECT_EQ(parse_not_acknowledged(Reply{0x92, {}, 0x10}), NotAcknowledgedReply{});
}

TEST(SickReplies, TypeTextIsSentAsIs) {
  const TypeReply type{"LMS200;30106        "};
  const Reply reply = unframe_reply(encode_reply(type));
  EXPECT_EQ(reply.code, 0xBA);
  EXPECT_EQ(reply.data.size(), 20u);
  EXPECT_EQ(reply.data[0], 'L');
  EXPECT_EQ(parse_type_reply(reply), type);
  EXPECT_EQ(type.trimmed(), "LMS200;30106");
  EXPECT_EQ(TypeReply{"   "}.trimmed(), "");
}

TEST(SickReplies, VariantReplyLayout) {
  const VariantReply accepted{true, {100, 25}};
  const Reply reply = unframe_reply(encode_reply(accepted));
  // BB 01 w(2) r(2) status: LEN 7.
  EXPECT_EQ(reply, (Reply{0xBB, {0x01, 0x64, 0x00, 0x19, 0x00}, 0x10}));
  EXPECT_EQ(encode_reply(accepted)[2], 7);
  EXPECT_EQ(parse_variant_reply(reply), accepted);
  EXPECT_FALSE(parse_variant_reply(Reply{0xBB, {0x00, 0xB4, 0x00, 0x32, 0x00}, 0x10}).accepted);
}

TEST(SickReplies, ConfigReplyIsLen36) {
  const ConfigReply config{numbered_block()};
  const auto telegram = encode_reply(config);
  EXPECT_EQ(telegram[2], 36);
  EXPECT_EQ(telegram[3], 0);
  const Reply reply = unframe_reply(telegram);
  EXPECT_EQ(reply.data[5], 6);  // body[6], the measuring mode
  const ConfigReply parsed = parse_config_reply(reply);
  EXPECT_EQ(parsed, config);
  EXPECT_EQ(static_cast<int>(parsed.config.measuring_mode()), 6);
  EXPECT_EQ(static_cast<int>(parsed.config.unit()), 7);
  EXPECT_EQ(parsed.config.blanking(), 0x0201);
}

TEST(SickReplies, SetConfigReplyIsLen37) {
  const SetConfigReply config{true, numbered_block()};
  const auto telegram = encode_reply(config);
  EXPECT_EQ(telegram[2], 37);
  const Reply reply = unframe_reply(telegram);
  EXPECT_EQ(reply.data[0], 0x01);
  EXPECT_EQ(parse_set_config_reply(reply), config);
  EXPECT_FALSE(parse_set_config_reply(unframe_reply(encode_reply(SetConfigReply{false, {}}))).accepted);
}

void expect_parse_error(void (*parse)(const Reply&), const Reply& reply, const std::string& words) {
  try {
    parse(reply);
    ADD_FAILURE() << "accepted code " << int{reply.code} << " with " << reply.data.size() << " bytes";
  } catch (const TelegramError& error) {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(SickReplies, WrongCodesAndLengthsAreClearErrors) {
  expect_parse_error([](const Reply& r) { (void)parse_mode_reply(r); }, Reply{0x92, {0}, 0x10},
                     "A0 reply (switch mode): got reply code 92");
  expect_parse_error([](const Reply& r) { (void)parse_mode_reply(r); }, Reply{0xA0, {}, 0x10},
                     "truncated: expected 1 data bytes, got 0");
  expect_parse_error([](const Reply& r) { (void)parse_variant_reply(r); },
                     Reply{0xBB, {0x01, 0xB4}, 0x10}, "truncated");
  expect_parse_error([](const Reply& r) { (void)parse_config_reply(r); },
                     Reply{0xF4, std::vector<std::uint8_t>(33), 0x10},
                     "expected 34 data bytes, got 33");
  expect_parse_error([](const Reply& r) { (void)parse_config_reply(r); },
                     Reply{0xF4, std::vector<std::uint8_t>(35), 0x10}, "too long");
  expect_parse_error([](const Reply& r) { (void)parse_set_config_reply(r); },
                     Reply{0xF7, std::vector<std::uint8_t>(34), 0x10}, "expected 35");
  expect_parse_error([](const Reply& r) { (void)parse_type_reply(r); }, Reply{0xB0, {}, 0x10},
                     "got reply code B0");
  expect_parse_error([](const Reply& r) { (void)parse_not_acknowledged(r); },
                     Reply{0xA0, {0}, 0x10}, "got reply code A0");
}

}  // namespace replies_test
}  // namespace playerkit::hardware::sick
