#include "log/log_format_detection.hpp"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>
#include <unistd.h>

namespace playerkit::log {
namespace log_format_detection_test {

const std::filesystem::path kRadish = std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "radish";

LogFormat detect_text(const std::string& text) {
  std::istringstream in(text);
  return detect_log_format(in, "test.log");
}

std::string error_of(const std::string& text) {
  try {
    detect_text(text);
  } catch (const std::runtime_error& error) {
    return error.what();
  }
  return "no error";
}

TEST(LogFormatDetection, PlayerHeaderDecides) {
  EXPECT_EQ(detect_text("## Player version 1.5 \n## File version 0.0.0 \n"), LogFormat::kPlayer);
}

TEST(LogFormatDetection, PlayerDataLineWithoutHeaderDecides) {
  EXPECT_EQ(detect_text("# a comment\n\n0000000012.500 robot1 6665 position 00 0000000012.500 "
                        "+01.000 +02.000 +0.100 +00.000 +00.000 +00.000 0\n"),
            LogFormat::kPlayer);
}

TEST(LogFormatDetection, CarmenKeywordDecidesEvenWhenUnknown) {
  EXPECT_EQ(detect_text("# message formats defined: PARAM\nPARAM robot_x 1 nohost 0\n"), LogFormat::kCarmen);
  EXPECT_EQ(detect_text("#SEQUENTIAL EDGES\nVERTEX2 0 0 0 0\n"), LogFormat::kCarmen);
}

TEST(LogFormatDetection, ForeignLinesAreErrorsWithLineNumbers) {
  EXPECT_EQ(error_of("#\nhello world\n"),
            "test.log:2: neither a Player log line (\"<time> <host> <port> <interface> <index> "
            "<time> ...\") nor a CARMEN record (an upper-case keyword such as FLASER): 'hello world'");
  EXPECT_EQ(error_of(std::string("\x01\x02zz\n", 5)), "test.log:1: binary data, not a text log");
  EXPECT_EQ(error_of(""), "test.log: empty file, not a log");
  EXPECT_EQ(error_of("# only\n#comments\n"),
            "test.log: no Player or CARMEN line in its first 2 lines (only blank lines and comments)");
  // A time-first line with a bad port is not a Player line.
  EXPECT_NE(error_of("12.5 robot1 port laser 00 12.5\n").find("test.log:1: neither"), std::string::npos);
}

TEST(LogFormatDetection, BundledRadishLogsAreCarmenThroughGzip) {
  for (const char* name : {"intel-corrected.log.gz", "csail-corrected.log.gz", "intel-lab.flirtlib.excerpt.log.gz"}) {
    EXPECT_EQ(detect_log_format(kRadish / name), LogFormat::kCarmen) << name;
  }
}

TEST(LogFormatDetection, PlainPlayerFileAndMissingFile) {
  const auto path = std::filesystem::temp_directory_path() /
                    ("log_format_detection_" + std::to_string(::getpid()) + ".log");
  std::ofstream(path) << "## Player version 1.5 \n";
  EXPECT_EQ(detect_log_format(path), LogFormat::kPlayer);
  std::filesystem::remove(path);
  EXPECT_THROW(detect_log_format(path), std::runtime_error);
  EXPECT_EQ(to_string(LogFormat::kCarmen), "carmen");
}

}  // namespace log_format_detection_test
}  // namespace playerkit::log
