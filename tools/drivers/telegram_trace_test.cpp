#include "telegram_trace.hpp"

#include "families/builtin_families.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>
#include <vector>

namespace playerkit::player_drivers {
namespace telegram_trace_test {

using Bytes = std::vector<std::uint8_t>;
using Kind = TracePiece::Kind;

// The splitter is checked on the framing of real families, when they are built.
families::TraceFraming framing_of(const char* family) {
  return families::builtin_families().framing(family);
}

// p2os.md §1.1: SYNC0 and OPEN as the sheet writes them.
const Bytes kSync0 = {0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00};
const Bytes kOpen = {0xFA, 0xFB, 0x03, 0x01, 0x00, 0x01};
// An ACK byte, then A0 00 with status 10 and its CRC (sicklms200.md).
const Bytes kSickAckAndModeReply = {0x06, 0x02, 0x80, 0x03, 0x00, 0xA0, 0x00, 0x10, 0x16, 0x0A};

TEST(TelegramSplitter, ATelegramSplitOverReadsComesOutWhole) {
  if (!framing_of("p2os").incoming) GTEST_SKIP() << "the p2os family is left out of this build";
  TelegramSplitter splitter(framing_of("p2os").incoming);
  EXPECT_TRUE(splitter.feed(Bytes(kSync0.begin(), kSync0.begin() + 4)).empty());
  EXPECT_EQ(splitter.feed(Bytes(kSync0.begin() + 4, kSync0.end())), (std::vector<TracePiece>{{Kind::telegram, kSync0}}));
}

TEST(TelegramSplitter, SeveralTelegramsInOneReadAndNoiseBetween) {
  if (!framing_of("p2os").incoming) GTEST_SKIP() << "the p2os family is left out of this build";
  TelegramSplitter splitter(framing_of("p2os").outgoing);
  Bytes bytes = {0x11, 0x22};
  bytes.insert(bytes.end(), kSync0.begin(), kSync0.end());
  bytes.push_back(0x33);
  bytes.insert(bytes.end(), kOpen.begin(), kOpen.end());
  EXPECT_EQ(splitter.feed(bytes), (std::vector<TracePiece>{{Kind::noise, {0x11, 0x22}},
                                                           {Kind::telegram, kSync0},
                                                           {Kind::noise, {0x33}},
                                                           {Kind::telegram, kOpen}}));
}

TEST(TelegramSplitter, ABadChecksumIsItsOwnPiece) {
  if (!framing_of("p2os").incoming) GTEST_SKIP() << "the p2os family is left out of this build";
  TelegramSplitter splitter(framing_of("p2os").incoming);
  const Bytes corrupt = {0xFA, 0xFB, 0x03, 0x00, 0x00, 0x01};
  const auto pieces = splitter.feed(corrupt);
  ASSERT_FALSE(pieces.empty());
  EXPECT_EQ(pieces.front(), (TracePiece{Kind::bad_checksum, corrupt}));
}

TEST(TelegramSplitter, SickAckByteThenReply) {
  if (!framing_of("sick").incoming) GTEST_SKIP() << "the sick family is left out of this build";
  TelegramSplitter splitter(framing_of("sick").incoming);
  EXPECT_EQ(splitter.feed(kSickAckAndModeReply),
            (std::vector<TracePiece>{{Kind::noise, {0x06}},
                                     {Kind::telegram, Bytes(kSickAckAndModeReply.begin() + 1, kSickAckAndModeReply.end())}}));
}

TEST(TelegramSplitter, WithoutAFormatEveryChunkAsItCame) {
  TelegramSplitter splitter(framing_of("null").incoming);
  EXPECT_EQ(splitter.feed(Bytes{1, 2, 3}), (std::vector<TracePiece>{{Kind::raw, {1, 2, 3}}}));
  EXPECT_TRUE(splitter.feed(Bytes{}).empty());
}

TEST(TelegramSplitter, FlushGivesTheUnfinishedRest) {
  if (!framing_of("p2os").incoming) GTEST_SKIP() << "the p2os family is left out of this build";
  TelegramSplitter splitter(framing_of("p2os").incoming);
  EXPECT_TRUE(splitter.feed(Bytes{0xFA, 0xFB, 0x03}).empty());
  EXPECT_EQ(splitter.flush(), (std::vector<TracePiece>{{Kind::noise, {0xFA, 0xFB, 0x03}}}));
  EXPECT_TRUE(splitter.flush().empty());
}

TEST(TelegramTrace, OneLinePerTelegramWithDirectionAndTime) {
  if (!framing_of("sick").incoming) GTEST_SKIP() << "the sick family is left out of this build";
  std::vector<std::string> lines;
  auto trace = telegram_trace("laser:0", framing_of("sick"), [&lines](std::string_view line) {
    lines.emplace_back(line);
  });
  const auto now = std::chrono::steady_clock::now();
  trace(false, kSickAckAndModeReply, now);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[0].rfind("trace laser:0 ", 0), 0u) << lines[0];
  EXPECT_NE(lines[0].find(" < 06  (not a telegram)"), std::string::npos) << lines[0];
  EXPECT_NE(lines[1].find(" < 02 80 03 00 A0 00 10 16 0A"), std::string::npos) << lines[1];
  trace(true, Bytes{0x02, 0x00}, now);
  EXPECT_EQ(lines.size(), 2u);  // half a request: nothing yet
}

}  // namespace telegram_trace_test
}  // namespace playerkit::player_drivers
