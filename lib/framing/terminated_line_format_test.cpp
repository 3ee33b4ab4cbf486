#include "framing/terminated_line_format.hpp"

#include <gtest/gtest.h>

#include "framing/test_support.hpp"

namespace playerkit::framing {
namespace terminated_line_format_test {

using namespace test_support;
using Kind = FrameScan::Kind;

std::vector<std::string> texts(const Cut& cut) {
  std::vector<std::string> out;
  for (const auto& frame : cut.frames) out.emplace_back(line_text(frame));
  return out;
}

TEST(TerminatedLineFormat, KheperaRepliesEndInCrLfAndCommandsInLf) {
  // khepera.md §1.1: reply `e,8,-8\r\n`, command `D,8,-8\n`.
  const TerminatedLineFormat replies({.end = LineEnd::cr_or_lf});
  const auto reply = text_bytes("e,8,-8\r\n");
  EXPECT_EQ(replies.scan(reply).kind, Kind::frame);
  EXPECT_EQ(replies.scan(reply).length, 8u);
  EXPECT_EQ(line_text(reply), "e,8,-8");

  const TerminatedLineFormat commands({.end = LineEnd::lf});
  const auto command = text_bytes("D,8,-8\nE\n");
  EXPECT_EQ(commands.scan(command).length, 7u);
  EXPECT_EQ(texts(cut(commands, command)), (std::vector<std::string>{"D,8,-8", "E"}));
}

TEST(TerminatedLineFormat, TheTelegramKeepsItsTerminator) {
  const TerminatedLineFormat format({.end = LineEnd::crlf});
  const Cut result = cut(format, text_bytes("$PGRMZ,125,f,3*1D\r\nabc\r\n"));
  ASSERT_EQ(result.frames.size(), 2u);
  EXPECT_EQ(result.frames[0], text_bytes("$PGRMZ,125,f,3*1D\r\n"));
  EXPECT_EQ(line_text(result.frames[1]), "abc");
}

TEST(TerminatedLineFormat, RebPromptIsALineOfItsOwn) {
  // reb.md §1.1: each reply `h,12345\r\n` is followed by the prompt `:\r\n`.
  const TerminatedLineFormat format({.end = LineEnd::cr_or_lf});
  const Cut result = cut(format, text_bytes("h,12345\r\n:\r\n"), 3);
  EXPECT_EQ(texts(result), (std::vector<std::string>{"h,12345", ":"}));
  EXPECT_EQ(result.skipped, 0u);
  EXPECT_EQ(result.left_over, 0u);
}

TEST(TerminatedLineFormat, CrOrLfEndsAtEitherAndTakesACrLfPairAsOne) {
  const TerminatedLineFormat format({.end = LineEnd::cr_or_lf});
  // A CR-only device (a real PTU-46, ptu46.md §1) next to CR LF and LF lines.
  const Cut whole = cut(format, text_bytes("* 583\r* 1000\r\n!P\n"), 64);
  EXPECT_EQ(texts(whole), (std::vector<std::string>{"* 583", "* 1000", "!P"}));
  EXPECT_EQ(whole.frames[1].size(), 8u);
  EXPECT_EQ(whole.skipped, 0u);
}

TEST(TerminatedLineFormat, ACrLfPairSplitAcrossReadsEndsTheLineAtTheCr) {
  const TerminatedLineFormat format({.end = LineEnd::cr_or_lf});
  // The CR is the last byte buffered: the line is out at once, not held
  // back for an LF that a CR-only device never sends.
  const auto first = text_bytes("e,8,-8\r");
  EXPECT_EQ(format.scan(first).kind, Kind::frame);
  EXPECT_EQ(format.scan(first).length, 7u);
  // The LF arriving later is the pair's tail, dropped, not an empty line.
  EXPECT_EQ(format.scan(text_bytes("\nh,1\r\n")).kind, Kind::skip);
  EXPECT_EQ(format.scan(text_bytes("\nh,1\r\n")).length, 1u);
  const Cut byte_by_byte = cut(format, text_bytes("e,8,-8\r\nh,1\r\n"));
  EXPECT_EQ(texts(byte_by_byte), (std::vector<std::string>{"e,8,-8", "h,1"}));
}

TEST(TerminatedLineFormat, CrLfModeKeepsLoneCrAndLfAsText) {
  const TerminatedLineFormat format({.end = LineEnd::crlf});
  EXPECT_EQ(format.scan(text_bytes("a\rb\nc\r")).kind, Kind::need_more);
  const auto line = text_bytes("a\rb\nc\r\n");
  EXPECT_EQ(format.scan(line).length, line.size());
}

TEST(TerminatedLineFormat, CrModeLeavesLfInTheNextLine) {
  // REB commands end in CR (reb.md §1.1): `D,2,-24\r`.
  const TerminatedLineFormat format({.end = LineEnd::cr});
  const Cut result = cut(format, text_bytes("D,2,-24\rH\r"));
  EXPECT_EQ(texts(result), (std::vector<std::string>{"D,2,-24", "H"}));
  EXPECT_EQ(line_text(cut(format, text_bytes("x\r\ny\r")).frames[1]), "\ny");
}

TEST(TerminatedLineFormat, CmucamPromptIsATelegramWithoutTerminator) {
  // cmucam2.md §2: `PM 1` CR is answered `ACK` CR `:` (5 bytes); the T packet
  // follows its ACK, and the idle prompt has no terminator.
  const TerminatedLineFormat format({.end = LineEnd::cr, .prompt = std::uint8_t{':'}});
  const Cut result = cut(format, text_bytes("ACK\r:ACK\rT 40 50 30 40 50 60 12 80\r:"), 4);
  EXPECT_EQ(texts(result), (std::vector<std::string>{"ACK", ":", "ACK", "T 40 50 30 40 50 60 12 80", ":"}));
  EXPECT_EQ(result.left_over, 0u);
  // A ':' inside a line is text.
  EXPECT_EQ(format.scan(text_bytes("a:b\r")).length, 4u);
}

TEST(TerminatedLineFormat, EmptyLinesAreTelegramsUnlessSkipped) {
  // A Khepera emulator sees the driver's start-up CR LF (khepera.md §6).
  const auto stream = text_bytes("\r\nE\n\n");
  const TerminatedLineFormat kept({.end = LineEnd::lf});
  EXPECT_EQ(texts(cut(kept, stream)), (std::vector<std::string>{"", "E", ""}));
  const TerminatedLineFormat skipped({.end = LineEnd::cr_or_lf, .skip_empty_lines = true});
  const Cut result = cut(skipped, stream);
  EXPECT_EQ(texts(result), (std::vector<std::string>{"E"}));
  EXPECT_EQ(result.skipped, 3u);
}

TEST(TerminatedLineFormat, AnOverlongLineIsNoiseUpToItsTerminator) {
  const TerminatedLineFormat format({.end = LineEnd::lf, .max_length = 8});
  // Exactly the longest line, terminator included.
  EXPECT_EQ(format.scan(text_bytes("1234567\n")).kind, Kind::frame);
  const auto overlong = text_bytes("12345678\nok\n");
  EXPECT_EQ(format.scan(overlong).kind, Kind::skip);
  EXPECT_EQ(format.scan(overlong).length, 9u);
  const Cut result = cut(format, overlong, 100);
  EXPECT_EQ(texts(result), (std::vector<std::string>{"ok"}));
  EXPECT_EQ(result.skipped, 9u);
}

TEST(TerminatedLineFormat, EndlessGarbageNeverWaitsBeyondTheLongestLine) {
  const TerminatedLineFormat format({.end = LineEnd::crlf, .max_length = 16});
  const Bytes garbage(1000, 'x');
  // The line's tail after the last full drop may come out as a line of its
  // own (the format keeps no state); the real line after it always does.
  for (const std::size_t piece : {std::size_t{1}, std::size_t{7}, std::size_t{64}}) {
    const Cut result = cut(format, concat({garbage, text_bytes("\r\nok\r\n")}), piece);
    EXPECT_LT(result.left_over, 16u);
    ASSERT_FALSE(result.frames.empty()) << piece;
    EXPECT_EQ(line_text(result.frames.back()), "ok") << piece;
  }
  // With nothing but garbage, what stays buffered is always shorter than a line.
  EXPECT_LT(cut(format, garbage, 5).left_over, 16u);
}

TEST(TerminatedLineFormat, EmptyBufferWaits) {
  const TerminatedLineFormat format;
  EXPECT_EQ(format.scan({}).kind, Kind::need_more);
  EXPECT_EQ(format.scan(text_bytes("partial")).kind, Kind::need_more);
  EXPECT_EQ(format.name(), "line");
  EXPECT_EQ(TerminatedLineFormat({.name = "echo"}).name(), "echo");
}

TEST(TerminatedLineFormat, LineBytesRoundTripThroughEachEnd) {
  for (const LineEnd end : {LineEnd::lf, LineEnd::cr, LineEnd::crlf, LineEnd::cr_or_lf}) {
    const TerminatedLineFormat format({.end = end});
    const auto stream = concat({line_bytes("D,8,-8", end), line_bytes("", end), line_bytes("N", end)});
    EXPECT_EQ(texts(cut(format, stream)), (std::vector<std::string>{"D,8,-8", "", "N"}))
        << static_cast<int>(end);
  }
  EXPECT_EQ(line_bytes("e", LineEnd::cr_or_lf), text_bytes("e\r\n"));
  EXPECT_EQ(line_bytes("e", LineEnd::cr), text_bytes("e\r"));
}

TEST(TerminatedLineFormat, LineTextRemovesOneTerminatorOnly) {
  EXPECT_EQ(line_text(text_bytes("a\r\n")), "a");
  EXPECT_EQ(line_text(text_bytes("a\n\n")), "a\n");
  EXPECT_EQ(line_text(text_bytes("a\r\r")), "a\r");
  EXPECT_EQ(line_text(text_bytes(":")), ":");
  EXPECT_EQ(line_text({}), "");
}

}  // namespace terminated_line_format_test
}  // namespace playerkit::framing
