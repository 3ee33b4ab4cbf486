#include "text/printable.hpp"

#include <gtest/gtest.h>

#include <string>

namespace playerkit::text {
namespace printable_test {

TEST(Printable, KeepsPrintableAsciiAndUtf8) {
  EXPECT_EQ(printable("laser:0 ( driver \"sicklms200\" )"), "laser:0 ( driver \"sicklms200\" )");
  EXPECT_EQ(printable("caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\xa4\x96"), "caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\xa4\x96");
}

TEST(Printable, EscapesTerminalControls) {
  // An ANSI "clear screen" and a colour change must reach the terminal as text.
  EXPECT_EQ(printable("a\x1b[2Jb\x1b[31m"), "a\\x1b[2Jb\\x1b[31m");
  EXPECT_EQ(printable("one\ntwo\r\tthree"), "one\\ntwo\\r\\tthree");
  EXPECT_EQ(printable(std::string("nul\0bell\a del\x7f", 14)), "nul\\x00bell\\x07 del\\x7f");
}

TEST(Printable, EscapesInvalidUtf8ByteByByte) {
  EXPECT_EQ(printable("\xff\xfe"), "\\xff\\xfe");
  EXPECT_EQ(printable("\x80"), "\\x80");                  // a continuation byte alone
  EXPECT_EQ(printable("\xc0\xaf"), "\\xc0\\xaf");         // an overlong '/'
  EXPECT_EQ(printable("\xed\xa0\x80"), "\\xed\\xa0\\x80");  // a surrogate
  EXPECT_EQ(printable("\xe2\x82"), "\\xe2\\x82");         // cut short
  EXPECT_EQ(printable("\xf4\x90\x80\x80"), "\\xf4\\x90\\x80\\x80");  // beyond U+10FFFF
}

TEST(Printable, EscapesC1ControlsAndBidiOverrides) {
  EXPECT_EQ(printable("\xc2\x9b" "31m"), "\\u009b31m");  // CSI as a C1 control
  EXPECT_EQ(printable("abc\xe2\x80\xae" "fed"), "abc\\u202efed");
  EXPECT_EQ(printable("a\xe2\x80\xa8" "b"), "a\\u2028b");
}

TEST(Printable, EscapingTwiceChangesNothing) {
  const std::string once = printable("x\x1b[0m\xff\n\\y");
  EXPECT_EQ(printable(once), once);
  EXPECT_EQ(once, "x\\x1b[0m\\xff\\n\\y");
}

TEST(Excerpt, ShortTextIsOnlyEscaped) {
  EXPECT_EQ(excerpt("sicklms2000"), "sicklms2000");
  EXPECT_EQ(excerpt(std::string(kMaxExcerptBytes, 'a')), std::string(kMaxExcerptBytes, 'a'));
}

TEST(Excerpt, LongTextIsCutWithAnEllipsis) {
  EXPECT_EQ(excerpt(std::string(1'000'000, 'x')), std::string(kMaxExcerptBytes, 'x') + "\u2026");
  EXPECT_EQ(excerpt("abcdef", 4), "abcd\u2026");
}

TEST(Excerpt, NeverCutsAnEscapeOrACharacter) {
  // "ab" then a 4-byte escape: 6 bytes do not fit in 5.
  EXPECT_EQ(excerpt("ab\x1b" "cd", 5), "ab\u2026");
  EXPECT_EQ(excerpt("ab\xc3\xa9" "cd", 3), "ab\u2026");
  EXPECT_EQ(excerpt("ab\xc3\xa9" "cd", 4), "ab\xc3\xa9\u2026");
}

TEST(DescribeCharacter, QuotesPrintableAsciiAndNamesOtherBytesInHex) {
  EXPECT_EQ(describe_character(','), "character ','");
  EXPECT_EQ(describe_character('\x1b'), "byte 0x1B");
  EXPECT_EQ(describe_character('\x7f'), "byte 0x7F");
  EXPECT_EQ(describe_character(static_cast<char>(0xC3)), "byte 0xC3");
}

}  // namespace printable_test
}  // namespace playerkit::text
