// audit_log_times on files, and the readers applying the clock: a log with
// good times reads exactly as without a clock; one without gets file order.

#include "log/log_clock_reader.hpp"

#include <gtest/gtest.h>
#include <stdlib.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "log/carmen_log_reader.hpp"
#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"

namespace playerkit::log {
namespace log_clock_reader_test {

class LogClockReaderTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::string pattern = (std::filesystem::temp_directory_path() / "log_clock_reader_test.XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    directory_ = pattern;
    previous_handler_ = set_log_clock_warning_handler([this](const std::string& w) { warnings_.push_back(w); });
  }
  void TearDown() override {
    set_log_clock_warning_handler(previous_handler_);
    std::filesystem::remove_all(directory_);
  }
  std::filesystem::path write(const std::string& name, const std::string& text) {
    const auto path = directory_ / name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  std::filesystem::path directory_;
  std::vector<std::string> warnings_;
  LogClockWarningHandler previous_handler_;
};

// A CARMEN log of n scans with their ODOM lines, every time `time`.
std::string carmen_log(int n, const std::string& time) {
  std::string text = "PARAM robot_front_laser_max 50 1071078718.46 merci 1071078718.46\n";
  for (int i = 0; i < n; ++i) {
    const std::string x = std::to_string(i);
    text += "ODOM " + x + " 0 0 0 0 0 " + time + " pippo " + time + "\n";
    text += "FLASER 2 1.5 2.5 " + x + " 0 0 " + x + " 0 0 " + time + " pippo " + time + "\nNEFF 60\n";
  }
  return text;
}

// A Player log of n position lines, `step` seconds apart from `start`.
std::string player_log(int n, double start, double step) {
  std::string text = "## Player version 1.5 \n## File version 0.0.0 \n";
  for (int i = 0; i < n; ++i) {
    char line[200];
    const double t = start + step * i;
    std::snprintf(line, sizeof line, "%014.3f robot1 6665 position 00 %014.3f +00.%03d +00.000 +0.000 +0.000 +0.000 +0.000 0 \n",
                  t, t, i % 1000);
    text += line;
  }
  return text;
}

std::vector<DataLine> read_player(const std::filesystem::path& path, std::shared_ptr<const LogClock> clock) {
  auto in = open_log_input(path);
  TextLogReader reader(*in, path.string(), {.clock = std::move(clock)});
  std::vector<DataLine> lines;
  while (auto line = reader.next()) lines.push_back(std::get<DataLine>(*line));
  return lines;
}

TEST_F(LogClockReaderTest, ACarmenLogStampedZeroReadsInFileOrderWithTheSyntheticClock) {
  const auto path = write("zero.log", carmen_log(12, "0"));
  const auto clock = audit_log_times(path);
  ASSERT_TRUE(clock->synthetic());
  EXPECT_EQ(clock->records(), 24u);  // not the PARAM
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_EQ(warnings_[0], path.string() +
                              ": 24 of 24 timestamps unusable (all 0); using file order with a synthetic 10 Hz clock");
  audit_log_times(path);  // a second reader of the same file: no second warning
  EXPECT_EQ(warnings_.size(), 1u);

  auto in = open_log_input(path);
  CarmenLogReader reader(*in, path.string(), {.clock = clock});
  std::vector<double> times;
  while (auto record = reader.next()) {
    const auto stamp = std::visit([](const auto& r) { return r.stamp; }, *record);
    if (std::holds_alternative<CarmenParam>(*record)) {
      EXPECT_DOUBLE_EQ(stamp.ipc_timestamp, 1071078718.46);  // configuration keeps its stamp
      continue;
    }
    EXPECT_DOUBLE_EQ(stamp.ipc_timestamp, stamp.logger_timestamp);
    times.push_back(stamp.ipc_timestamp);
  }
  ASSERT_EQ(times.size(), 24u);
  for (std::size_t i = 0; i < times.size(); ++i) EXPECT_DOUBLE_EQ(times[i], static_cast<double>(i) / 10) << i;
  EXPECT_EQ(reader.timed_records(), 24u);
}

TEST_F(LogClockReaderTest, APlayerLogWithGoodTimesReadsAsWithoutAClock) {
  const auto path = write("good.log", player_log(30, 1000.0, 0.1));
  const auto clock = audit_log_times(path);
  EXPECT_EQ(clock->repair(), LogTimeRepair::kNone);
  EXPECT_TRUE(warnings_.empty());
  const auto with = read_player(path, clock);
  const auto without = read_player(path, nullptr);
  ASSERT_EQ(with.size(), 30u);
  ASSERT_EQ(with.size(), without.size());
  for (std::size_t i = 0; i < with.size(); ++i) {
    EXPECT_EQ(with[i].server_time, without[i].server_time);
    EXPECT_EQ(with[i].data_time, without[i].data_time);
    EXPECT_EQ(with[i].message.header.time_sec, without[i].message.header.time_sec);
    EXPECT_EQ(with[i].message.header.timestamp_usec, without[i].message.header.timestamp_usec);
    EXPECT_EQ(with[i].message.payload, without[i].message.payload);
  }
}

TEST_F(LogClockReaderTest, APlayerLineGoingBackIsInterpolatedInEveryTimeField) {
  std::string text = player_log(20, 1000.0, 1.0);
  const auto at = text.find("00001010.000");  // line 11 of 20: both times go back 600 s
  text.replace(at, 12, "00000410.000");
  text.replace(text.find("00001010.000"), 12, "00000410.000");
  const auto path = write("back.log", text);
  const auto clock = audit_log_times(path);
  EXPECT_EQ(clock->repair(), LogTimeRepair::kInterpolated);
  ASSERT_EQ(warnings_.size(), 1u);
  EXPECT_NE(warnings_[0].find("1 of 20 timestamps unusable (1 out of order by more than 1 s)"), std::string::npos);
  const auto lines = read_player(path, clock);
  ASSERT_EQ(lines.size(), 20u);
  EXPECT_EQ(lines[10].server_time.seconds(), 1010.0);
  EXPECT_EQ(lines[10].data_time.seconds(), 1010.0);
  EXPECT_EQ(lines[10].message.time().seconds(), 1010.0);
  EXPECT_EQ(lines[10].message.timestamp().seconds(), 1010.0);
  EXPECT_EQ(lines[9].server_time.seconds(), 1009.0);
}

TEST_F(LogClockReaderTest, ReadLogTimesGivesTheFileClock) {
  const auto path = write("times.log", player_log(3, 5.0, 0.5));
  EXPECT_EQ(read_log_times(path), (std::vector<double>{5.0, 5.5, 6.0}));
}

}  // namespace log_clock_reader_test
}  // namespace playerkit::log
