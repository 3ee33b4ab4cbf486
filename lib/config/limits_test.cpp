// The limits of limits.hpp, and messages that quote input safely.

#include "config/limits.hpp"

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <string>

#include "config/config_file.hpp"
#include "config/includes.hpp"
#include "config/test_support.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::config {
namespace limits_test {

using testing::error_of;
using Scratch = playerkit::testing::ScratchDirectory;

std::string load_error(const std::string& path) {
  return error_of([&] { (void)ConfigFile::load(path); });
}

TEST(ConfigLimits, IncludingADeviceIsRefusedWithoutReadingIt) {
  // /dev/zero never ends: reading it grew to 1.5 GB in 6 s.
  EXPECT_EQ(error_of([] { (void)tokenize_with_includes("\ninclude \"/dev/zero\"\n", "x.cfg"); }),
            "x.cfg:2:9: cannot read include file '/dev/zero': it is not a regular file (a device, a pipe "
            "or a socket) (looked for /dev/zero)");
  EXPECT_EQ(load_error("/dev/zero"),
            "/dev/zero: cannot read config file: it is not a regular file (a device, a pipe or a socket)");
}

TEST(ConfigLimits, IncludingAPipeDoesNotWaitForAWriter) {
  Scratch scratch("config_limits_test");
  const std::string pipe = scratch.file("pipe.cfg").string();
  ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
  EXPECT_EQ(load_error(pipe),
            pipe + ": cannot read config file: it is not a regular file (a device, a pipe or a socket)");
}

TEST(ConfigLimits, ADirectoryIsNotAConfiguration) {
  Scratch scratch("config_limits_test");
  const auto main = scratch.write("main.cfg", "include \".\"\n");
  EXPECT_EQ(load_error(main.string()),
            main.string() + ":1:9: cannot read include file '.': it is a directory, not a file (looked for " +
                scratch.path().string() + "/.)");
  EXPECT_EQ(load_error(scratch.path().string()),
            scratch.path().string() + ": cannot read config file: it is a directory, not a file");
}

TEST(ConfigLimits, AFileOverTheSizeLimitIsRefused) {
  Scratch scratch("config_limits_test");
  const std::string comment = "#" + std::string(1000, 'x') + "\n";
  std::string big;
  while (big.size() <= kMaxConfigBytes) big += comment;
  const auto path = scratch.write("big.cfg", big);
  const std::string too_large = "too large: a configuration with its includes may have " +
                                std::to_string(kMaxConfigBytes) + " bytes at most";
  EXPECT_EQ(load_error(path.string()), path.string() + ": cannot read config file: " + too_large);
  EXPECT_EQ(error_of([&] { (void)ConfigFile::parse(big, "text.cfg"); }),
            "text.cfg: the configuration is larger than " + std::to_string(kMaxConfigBytes) + " bytes");
}

TEST(ConfigLimits, TheSizeLimitCountsEveryIncludedFile) {
  Scratch scratch("config_limits_test");
  // Two halves fit on their own, but not together with the main file.
  std::string half;
  while (half.size() + 1000 < kMaxConfigBytes / 2) half += "#" + std::string(998, 'h') + "\n";
  half += std::string(kMaxConfigBytes / 2 - half.size(), '\n');
  scratch.write("a.cfg", half);
  scratch.write("b.cfg", half);
  const auto main = scratch.write("main.cfg", "include \"a.cfg\"\ninclude \"b.cfg\"\n");
  const std::string error = load_error(main.string());
  EXPECT_EQ(error.rfind(main.string() + ":2:9: cannot read include file 'b.cfg': too large", 0), 0u) << error;
}

TEST(ConfigLimits, IncludesNestOnlySoDeep) {
  Scratch scratch("config_limits_test");
  for (int i = 0; i <= kMaxIncludeDepth; ++i) {
    scratch.write("level" + std::to_string(i) + ".cfg", "include \"level" + std::to_string(i + 1) + ".cfg\"\n");
  }
  scratch.write("level" + std::to_string(kMaxIncludeDepth + 1) + ".cfg", "laser:0 ( )\n");
  // The main file includes level0; level0 .. level15 make 16 levels of includes.
  const auto main = scratch.write("main.cfg", "include \"level1.cfg\"\n");
  const std::string deepest = scratch.file("level" + std::to_string(kMaxIncludeDepth) + ".cfg").string();
  EXPECT_EQ(load_error(main.string()),
            deepest + ":1:9: include file 'level" + std::to_string(kMaxIncludeDepth + 1) +
                ".cfg': includes nested more than " + std::to_string(kMaxIncludeDepth) + " deep");
  // One level less is fine.
  const auto shallower = scratch.write("shallower.cfg", "include \"level2.cfg\"\n");
  EXPECT_EQ(ConfigFile::load(shallower).devices().size(), 1u);
}

TEST(ConfigLimits, OnlySoManyIncludes) {
  Scratch scratch("config_limits_test");
  scratch.write("empty.cfg", "");
  std::string main_text;
  for (int i = 0; i <= kMaxIncludedFiles; ++i) main_text += "include \"empty.cfg\"\n";
  const auto main = scratch.write("main.cfg", main_text);
  EXPECT_EQ(load_error(main.string()),
            main.string() + ":" + std::to_string(kMaxIncludedFiles + 1) + ":9: include file 'empty.cfg': more than " +
                std::to_string(kMaxIncludedFiles) + " includes in one configuration");
}

TEST(ConfigLimits, SectionsNestOnlySoDeep) {
  // 200000 levels overflowed the parser's stack.
  std::string deep;
  for (int i = 0; i < 200'000; ++i) deep += "a(\n";
  EXPECT_EQ(error_of([&] { (void)ConfigFile::parse(deep, "x.cfg"); }),
            "x.cfg:" + std::to_string(kMaxSectionDepth + 1) + ":1: sections nested more than " +
                std::to_string(kMaxSectionDepth) + " deep");
  // Through a macro too: its body's levels count where it is used.
  std::string macro = "define m position (";
  for (int i = 1; i < kMaxSectionDepth; ++i) macro += " null:" + std::to_string(i) + " (";
  macro += std::string(kMaxSectionDepth - 1, ')') + " )\n";
  EXPECT_EQ(ConfigFile::parse(macro + "m ( )\n", "x.cfg").devices().size(), static_cast<std::size_t>(kMaxSectionDepth));
  EXPECT_EQ(error_of([&] { (void)ConfigFile::parse(macro + "robot:7000 ( m ( ) )\n", "x.cfg"); }),
            "x.cfg:2:14: sections nested more than " + std::to_string(kMaxSectionDepth) + " deep");
}

TEST(ConfigLimits, MacrosOfMacrosCannotMultiplyWithoutBound) {
  // Each macro holds two of the one before: 40 lines would make 2^40 sections.
  std::string text = "define m0 position ( x [ 1 2 3 4 5 6 7 8 ] )\n";
  for (int i = 1; i <= 40; ++i) {
    const std::string before = "m" + std::to_string(i - 1);
    text += "define m" + std::to_string(i) + " position ( " + before + " ( ) " + before + " ( ) )\n";
  }
  text += "m40 ( )\n";
  const std::string error = error_of([&] { (void)ConfigFile::parse(text, "x.cfg"); });
  EXPECT_NE(error.find(": more than " + std::to_string(kMaxConfigItems) +
                       " sections and values once macros are expanded"),
            std::string::npos)
      << error;
}

TEST(ConfigLimits, ALineOverTheLimitIsReportedWithoutQuotingIt) {
  const std::string text = "laser:0 ( )\nposition:0 ( driver \"" + std::string(kMaxConfigLineBytes, 'p') + "\" )\n";
  EXPECT_EQ(error_of([&] { (void)ConfigFile::parse(text, "x.cfg"); }),
            "x.cfg:2:" + std::to_string(kMaxConfigLineBytes + 1) + ": line longer than " +
                std::to_string(kMaxConfigLineBytes) + " bytes");
  // A line at the limit is read.
  const std::string comment = "#" + std::string(kMaxConfigLineBytes - 1, 'c') + "\r\nlaser:0 ( )\n";
  EXPECT_EQ(ConfigFile::parse(comment, "x.cfg").devices().size(), 1u);
}

TEST(ConfigMessages, QuotedInputIsEscaped) {
  // A driver name holding "clear the screen": the terminal gets it as text.
  EXPECT_EQ(error_of([] { (void)ConfigFile::parse("laser:0 ( driver \"x\x1b[2J\xff\" )\n", "x.cfg"); }),
            "x.cfg:1:18: unknown driver 'x\\x1b[2J\\xff' for laser:0");
  EXPECT_EQ(error_of([] { (void)ConfigFile::parse("laser:0 ( port \"a\"b\x07 )\n", "x.cfg"); }),
            "x.cfg:1:20: syntax error: unexpected byte 0x07");
}

TEST(ConfigMessages, LongWordsAreCut) {
  const std::string name(5000, 'd');
  EXPECT_EQ(error_of([&] { (void)ConfigFile::parse("laser:0 ( driver \"" + name + "\" )\n", "x.cfg"); }),
            "x.cfg:1:18: unknown driver '" + std::string(80, 'd') + "\u2026' for laser:0");
  EXPECT_EQ(error_of([&] { (void)ConfigFile::parse(name + ":0 ( )\n", "x.cfg"); }),
            "x.cfg:1:1: unknown interface '" + std::string(80, 'd') + "\u2026'");
}

TEST(ConfigMessages, TheFileNameIsEscapedToo) {
  EXPECT_EQ(error_of([] { (void)ConfigFile::parse("lazer:0 ( )\n", "evil\x1b]0;title\x07.cfg"); }),
            "evil\\x1b]0;title\\x07.cfg:1:1: unknown interface 'lazer' (did you mean 'laser'?)");
}

}  // namespace limits_test
}  // namespace playerkit::config
