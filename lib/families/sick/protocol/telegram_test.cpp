#include "families/sick/protocol/telegram.hpp"

#include "families/sick/protocol/crc.hpp"
#include "families/sick/protocol/test_bytes.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::sick {
namespace telegram_test {

using testing::bytes;

// Every host telegram of sicklms200.md §1.4 and sickpls.md §1, as a body and
// the bytes the sheet computed for it.
struct Golden {
  const char* body;
  const char* telegram;
};
constexpr Golden kHostTelegrams[] = {
    {"20 00 53 49 43 4B 5F 4C 4D 53", "02 00 0A 00 20 00 53 49 43 4B 5F 4C 4D 53 BE C5"},
    {"20 00 53 49 43 4B 5F 50 4C 53", "02 00 0A 00 20 00 53 49 43 4B 5F 50 4C 53 CC FC"},
    {"20 40", "02 00 02 00 20 40 50 08"},
    {"20 42", "02 00 02 00 20 42 52 08"},
    {"20 48", "02 00 02 00 20 48 58 08"},
    {"20 24", "02 00 02 00 20 24 34 08"},
    {"3A", "02 00 01 00 3A 1E 12"},
    {"74", "02 00 01 00 74 50 12"},
    {"3B B4 00 32 00", "02 00 05 00 3B B4 00 32 00 3B 1F"},
    {"3B 64 00 19 00", "02 00 05 00 3B 64 00 19 00 E7 72"},
    {"3B B4 00 64 00", "02 00 05 00 3B B4 00 64 00 97 49"},
    {"20 27 01 00 B5 00", "02 00 06 00 20 27 01 00 B5 00 12 09"},
    {"20 27 01 00 91 01", "02 00 06 00 20 27 01 00 91 01 5B 2D"},
};

TEST(SickTelegram, FramesEveryHostTelegramOfTheSheets) {
  for (const Golden& golden : kHostTelegrams) {
    EXPECT_EQ(frame_request(bytes(golden.body)), bytes(golden.telegram)) << golden.body;
    EXPECT_EQ(unframe_request(bytes(golden.telegram)), bytes(golden.body)) << golden.telegram;
  }
}

TEST(SickTelegram, FramesTheSheetsReplies) {
  EXPECT_EQ(frame_reply(0xA0, bytes("00")), bytes("02 80 03 00 A0 00 10 16 0A"));
  EXPECT_EQ(frame_reply(0x92, bytes("00"), 0x10), bytes("02 80 03 00 92 00 10 DE 6E"));
  const Reply ok = unframe_reply(bytes("02 80 03 00 A0 00 10 16 0A"));
  EXPECT_EQ(ok, (Reply{0xA0, {0x00}, 0x10}));
  EXPECT_EQ(frame_reply(ok), bytes("02 80 03 00 A0 00 10 16 0A"));
}

TEST(SickTelegram, ReplyWithoutDataHasCodeAndStatus) {
  const auto telegram = frame_reply(0x92, {}, 0x10);
  EXPECT_EQ(telegram.size(), 8u);
  EXPECT_EQ(unframe_reply(telegram), (Reply{0x92, {}, 0x10}));
}

TEST(SickTelegram, RefusesBodiesNoTelegramCanCarry) {
  EXPECT_THROW(frame_request({}), TelegramError);
  const std::vector<std::uint8_t> huge(kMaxBodyLength + 1, 0x00);
  EXPECT_THROW(frame_request(huge), TelegramError);
  EXPECT_THROW(frame_reply(0xB0, huge), TelegramError);
}

void expect_unframe_error(const std::vector<std::uint8_t>& telegram, const std::string& words) {
  try {
    (void)unframe_reply(telegram);
    ADD_FAILURE() << "accepted " << hex(telegram);
  } catch (const TelegramError& error) {
    EXPECT_NE(std::string(error.what()).find(words), std::string::npos) << error.what();
  }
}

TEST(SickTelegram, UnframingNamesWhatIsWrong) {
  expect_unframe_error(bytes("02 80 03"), "truncated");
  expect_unframe_error(bytes("03 80 03 00 A0 00 10 16 0A"), "STX");
  expect_unframe_error(bytes("02 81 03 00 A0 00 10 16 0A"), "address");
  expect_unframe_error(bytes("02 80 04 00 A0 00 10 16 0A"), "LEN 4");
  expect_unframe_error(bytes("02 80 03 00 A0 00 10 16 0A 00"), "LEN 3");
  expect_unframe_error(bytes("02 80 03 00 A0 01 10 16 0A"), "CRC 0A16");
  // A request is not a reply and the other way round.
  expect_unframe_error(bytes("02 00 01 00 3A 1E 12"), "address");
  EXPECT_THROW(unframe_request(bytes("02 80 03 00 A0 00 10 16 0A")), TelegramError);
  // LEN 1 holds a code but no status.
  auto short_reply = bytes("02 80 01 00 A0");
  const std::uint16_t crc = crc16(short_reply);
  short_reply.push_back(static_cast<std::uint8_t>(crc & 0xFF));
  short_reply.push_back(static_cast<std::uint8_t>(crc >> 8));
  expect_unframe_error(short_reply, "a reply has a code and a status byte");
}

TEST(SickTelegram, HexShortensLongInput) {
  EXPECT_EQ(hex(bytes("02 80 03")), "02 80 03");
  EXPECT_EQ(hex(std::vector<std::uint8_t>(20, 0xAB), 2), "AB AB ... (20 bytes)");
}

}  // namespace telegram_test
}  // namespace playerkit::hardware::sick
