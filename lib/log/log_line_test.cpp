// Log readers under hostile input: lines over text::kMaxLineBytes are
// reported without being kept or quoted, and messages quote fields escaped.

#include "log/log_line.hpp"

#include <gtest/gtest.h>
#include <zlib.h>

#include <sstream>
#include <string>

#include "log/carmen_log_reader.hpp"
#include "log/log_format_detection.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"
#include "support/scratch_directory.hpp"
#include "text/line_reader.hpp"

namespace playerkit::log {
namespace log_line_test {

const std::string kTooLong = "run.log:2:1048577: line longer than 1048576 bytes";

std::string long_line() { return "1.0 h 6665 power 00 1.0 " + std::string(text::kMaxLineBytes, '9') + "\n"; }

TEST(LogLine, ALineAtTheCapIsRead) {
  std::istringstream in(std::string(text::kMaxLineBytes, 'x') + "\nnext\n");
  std::string line;
  bool too_long = true;
  ASSERT_TRUE(read_log_line(in, line, too_long));
  EXPECT_FALSE(too_long);
  EXPECT_EQ(line.size(), text::kMaxLineBytes);
  ASSERT_TRUE(read_log_line(in, line, too_long));
  EXPECT_EQ(line, "next");
  EXPECT_FALSE(read_log_line(in, line, too_long));
}

TEST(LogLine, PlayerReaderSkipsALongLineAsMalformed) {
  std::istringstream in("1.0 h 6665 sync 00 1.0\n" + long_line() + "2.0 h 6665 power 00 2.0 12.5\n");
  TextLogReader reader(in, "run.log");
  ASSERT_TRUE(reader.next());
  const auto after = reader.next();
  ASSERT_TRUE(after);
  EXPECT_TRUE(std::holds_alternative<DataLine>(*after));
  EXPECT_FALSE(reader.next());
  EXPECT_EQ(reader.malformed_count(), 1u);
  ASSERT_EQ(reader.malformed_lines().size(), 1u);
  EXPECT_EQ(reader.malformed_lines()[0], kTooLong);
}

TEST(LogLine, PlayerReaderWhenStrictThrowsAndReadsOn) {
  std::istringstream in("1.0 h 6665 sync 00 1.0\n" + long_line() + "2.0 h 6665 sync 00 2.0\n");
  TextLogReader reader(in, "run.log", {.strict = true});
  ASSERT_TRUE(reader.next());
  try {
    (void)reader.next();
    FAIL() << "no error";
  } catch (const LogParseError& error) {
    EXPECT_EQ(error.what(), kTooLong);
    EXPECT_EQ(error.line(), 2);
  }
  EXPECT_TRUE(reader.next());
}

TEST(LogLine, CarmenReaderSkipsALongLineAsMalformed) {
  std::istringstream in("ODOM 1 2 0.5 0 0 0 100.0 host 0.0\nFLASER 3 " + std::string(text::kMaxLineBytes, '1') +
                        "\nODOM 2 2 0.5 0 0 0 101.0 host 0.0\n");
  CarmenLogReader reader(in, "run.log");
  EXPECT_TRUE(reader.next());
  EXPECT_TRUE(reader.next());
  EXPECT_FALSE(reader.next());
  EXPECT_EQ(reader.malformed_lines(), 1u);
  ASSERT_EQ(reader.malformed_messages().size(), 1u);
  EXPECT_EQ(reader.malformed_messages()[0], kTooLong);
}

TEST(LogLine, DetectionRefusesALongFirstLine) {
  std::istringstream in(std::string(text::kMaxLineBytes + 1, 'A'));
  try {
    (void)detect_log_format(in, "run.log");
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_EQ(std::string(error.what()), "run.log:1:1048577: line longer than 1048576 bytes");
  }
}

TEST(LogLine, DetectionQuotesAnExcerptEscaped) {
  std::istringstream in("hello\xff\xfe " + std::string(200, 'w') + "\n");
  try {
    (void)detect_log_format(in, "run.log");
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\xff'), std::string::npos) << message;
    EXPECT_NE(message.find("'hello\\xff\\xfe " + std::string(66, 'w') + "\u2026'"), std::string::npos) << message;
  }
}

TEST(LogLine, FieldsInMessagesAreEscapedAndCut) {
  std::istringstream in("1.0 h 6665 power 00 1.0 \x1b[31m" + std::string(300, 'r') + "\n");
  TextLogReader reader(in, "run.log", {.strict = true});
  try {
    (void)reader.next();
    FAIL() << "no error";
  } catch (const LogParseError& error) {
    const std::string message = error.what();
    EXPECT_EQ(message.find('\x1b'), std::string::npos) << message;
    EXPECT_NE(message.find("got '\\x1b[31m" + std::string(72, 'r') + "\u2026'"), std::string::npos) << message;
    EXPECT_LT(message.size(), 200u);
  }
}

TEST(LogLine, AGzipBombOfOneLineCostsOnlyTheCap) {
  // 64 MiB of one line compress to some 64 KB; reading it keeps 1 MiB at most.
  playerkit::testing::ScratchDirectory scratch("log_line_test");
  const auto path = scratch.file("bomb.log.gz");
  gzFile out = gzopen(path.c_str(), "wb9");
  ASSERT_NE(out, nullptr);
  gzputs(out, "1.0 h 6665 sync 00 1.0\n1.0 h 6665 power 00 1.0 ");
  const std::string block(1 << 20, '7');
  for (int i = 0; i < 64; ++i) ASSERT_EQ(gzwrite(out, block.data(), static_cast<unsigned>(block.size())), 1 << 20);
  gzputs(out, "\n2.0 h 6665 sync 00 2.0\n");
  ASSERT_EQ(gzclose(out), Z_OK);
  auto in = open_log_input(path);
  TextLogReader reader(*in, "bomb.log.gz");
  int lines = 0;
  while (reader.next()) ++lines;
  EXPECT_EQ(lines, 2);
  EXPECT_EQ(reader.malformed_count(), 1u);
  EXPECT_EQ(reader.malformed_lines().at(0), "bomb.log.gz:2:1048577: line longer than 1048576 bytes");
}

}  // namespace log_line_test
}  // namespace playerkit::log
