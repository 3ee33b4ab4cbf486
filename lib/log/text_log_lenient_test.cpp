// TextLogReader on malformed lines: skipped and counted by default, fatal
// when strict; and a gzip-compressed log read through open_log_input.

#include <gtest/gtest.h>
#include <unistd.h>
#include <zlib.h>

#include <filesystem>
#include <sstream>

#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"

namespace playerkit::log {
namespace text_log_lenient_test {

using protocol::Timestamp;

const std::string kLogWithTwoBadLines =
    "## Player version 1.5 \n"
    "## File version 0.0.0 \n"
    "1.000000 h 6665 sync 00 1.000000 \n"
    "1.100000 h 6665 truth 00 1.000 +0.000\n"          // line 4: y and heading missing
    "1.150 h 6665 power 00 1.150 twelve\n"             // line 5: not a number
    "1.200 h 6665 power 00 1.200 12.5\n"               // line 6: good, 3-decimal times
    "1.300000 h 6665 sync 00 1.300000 \n";

TEST(TextLogLenient, MalformedLinesAreSkippedAndCountedByDefault) {
  std::istringstream in(kLogWithTwoBadLines);
  TextLogReader reader(in, "run.log");
  std::vector<std::variant<SyncLine, DataLine>> lines;
  for (int i = 0; i < 10; ++i) {
    auto line = reader.next();
    if (!line) break;
    lines.push_back(std::move(*line));
  }
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(std::get<SyncLine>(lines[0]).server_time, (Timestamp{1, 0}));
  EXPECT_EQ(std::get<DataLine>(lines[1]).message.payload, (std::vector<std::uint8_t>{0, 125}));
  EXPECT_EQ(std::get<SyncLine>(lines[2]).server_time, (Timestamp{1, 300000}));
  EXPECT_EQ(reader.malformed_count(), 2u);
  EXPECT_EQ(reader.malformed_lines(),
            (std::vector<std::string>{"run.log:4:38: line ends before y",
                                      "run.log:5:29: volts: expected a number, got 'twelve'"}));
}

TEST(TextLogLenient, OnlyTheFirstFewErrorTextsAreKept) {
  std::string text;
  for (int i = 0; i < 5; ++i) text += "1.0 h 6665 power 00 1.0 x\n";
  std::istringstream in(text);
  TextLogReader reader(in, "many.log", {.strict = false, .kept_errors = 2});
  EXPECT_FALSE(reader.next().has_value());
  EXPECT_EQ(reader.malformed_count(), 5u);
  ASSERT_EQ(reader.malformed_lines().size(), 2u);
  EXPECT_EQ(reader.malformed_lines()[1].rfind("many.log:2:", 0), 0u) << reader.malformed_lines()[1];
}

TEST(TextLogLenient, StrictMakesTheFirstMalformedLineFatal) {
  std::istringstream in(kLogWithTwoBadLines);
  TextLogReader reader(in, "run.log", {.strict = true});
  ASSERT_TRUE(reader.next().has_value());
  try {
    reader.next();
    FAIL() << "no error";
  } catch (const LogParseError& error) {
    EXPECT_EQ(std::string(error.what()), "run.log:4:38: line ends before y");
  }
  EXPECT_EQ(reader.malformed_count(), 0u);
}

TEST(TextLogLenient, AnUnknownFileVersionIsFatalEvenWhenLenient) {
  std::istringstream in("## File version 9.9.9 \n1.0 h 6665 sync 00 1.0 \n");
  TextLogReader reader(in, "future.log");
  EXPECT_THROW(reader.next(), LogParseError);
}

TEST(TextLogLenient, AFileWithoutHeaderIsRead000) {
  std::istringstream in("1.0 h 6665 truth 00 1.0 +1.000 +2.000 +0.000\n");
  TextLogReader reader(in, "bare.log", {.strict = true});
  ASSERT_TRUE(reader.next().has_value());
  EXPECT_EQ(reader.format_version(), LogFormatVersion::k0_0_0);
  EXPECT_FALSE(reader.file_version().has_value());
}

TEST(TextLogLenient, AGzipLogReadsThroughOpenLogInput) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("text_log_lenient_" + std::to_string(::getpid()) + ".log.gz");
  const std::string text = "## Player version 1.6.5 \n## File version 0.2.0 \n" +
                           std::string("1086000000.000001 h 6665 truth 00 1086000000.000002 "
                                       "+01.500 -00.250 +00.000 +0.000 +0.000 +1.571\n");
  gzFile file = gzopen(path.c_str(), "wb");
  ASSERT_NE(file, nullptr);
  gzwrite(file, text.data(), static_cast<unsigned>(text.size()));
  gzclose(file);

  auto input = open_log_input(path);
  TextLogReader reader(*input, path.string(), {.strict = true});
  auto line = reader.next();
  std::filesystem::remove(path);
  ASSERT_TRUE(line.has_value());
  const auto& data = std::get<DataLine>(*line);
  EXPECT_EQ(data.server_time, (Timestamp{1086000000, 1}));
  EXPECT_EQ(data.data_time, (Timestamp{1086000000, 2}));
  EXPECT_EQ(data.message.payload.size(), 12u);
  EXPECT_EQ(reader.format_version(), LogFormatVersion::k0_2_0);
  EXPECT_FALSE(reader.next().has_value());
  EXPECT_FALSE(input->error().has_value());
}

}  // namespace text_log_lenient_test
}  // namespace playerkit::log
