// CarmenLogReader over hand-written logs: records in order, unknown lines and
// malformed lines counted, strict mode.

#include "log/carmen_log_reader.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace playerkit::log {
namespace carmen_log_reader_test {

const std::string kLog =
    "# CARMEN Logfile\n"                                       // 1
    "# message formats defined: PARAM SYNC ODOM FLASER\n"      // 2
    "PARAM robot_frontlaser_offset 0.0 nohost 0\n"             // 3
    "ODOM 0 0 0 0 0 0 0.000246 pippo 0.000246\n"               // 4
    "FLASER 2 1.5 2.5 1 2 3 1 2 3 0.5 pippo 0.5\n"             // 5
    "NEFF 15\n"                                                // 6
    "ODOM 1 2 oops 0 0 0 0.7 pippo 0.7\n"                      // 7
    "\n"                                                       // 8
    "VERTEX2 0 4.78 -5.84 -1.69\n"                             // 9
    "FLASER 3 1.5 2.5 1 2 3 1 2 3 0.9 pippo 0.9\n"             // 10
    "NEFF 14.8\n"                                              // 11
    "TRUEPOS 1 2 3 4 5 6 1.0 sim 1.0\n";                       // 12

TEST(CarmenLogReaderTest, ReadsRecordsInOrderAndCountsWhatItSkips) {
  std::istringstream in(kLog);
  CarmenLogReader reader(in, "run.log");
  auto first = reader.next();
  ASSERT_TRUE(first);
  EXPECT_EQ(std::get<CarmenParam>(*first).name, "robot_frontlaser_offset");
  EXPECT_EQ(reader.line_number(), 3);
  auto second = reader.next();
  ASSERT_TRUE(second);
  EXPECT_DOUBLE_EQ(std::get<CarmenOdometry>(*second).stamp.ipc_timestamp, 0.000246);
  auto third = reader.next();
  ASSERT_TRUE(third);
  EXPECT_EQ(std::get<CarmenLaser>(*third).ranges, (std::vector<double>{1.5, 2.5}));
  // Lines 6 to 11 hold no good record but the TRUEPOS at 12.
  auto fourth = reader.next();
  ASSERT_TRUE(fourth);
  EXPECT_EQ(std::get<CarmenTruePos>(*fourth).stamp.host, "sim");
  EXPECT_EQ(reader.line_number(), 12);
  EXPECT_FALSE(reader.next());
  EXPECT_FALSE(reader.next());

  EXPECT_EQ(reader.comment_lines(), 3u);
  EXPECT_EQ(reader.unknown_lines(), 3u);
  EXPECT_EQ(reader.unknown_keywords(), (std::map<std::string, std::size_t>{{"NEFF", 2}, {"VERTEX2", 1}}));
  EXPECT_EQ(reader.malformed_lines(), 2u);
  ASSERT_EQ(reader.malformed_messages().size(), 2u);
  EXPECT_EQ(reader.malformed_messages()[0], "run.log:7:10: odometry theta: expected a number, got 'oops'");
  EXPECT_EQ(reader.malformed_messages()[1].rfind("run.log:10:8: 3 readings announced, but 11 fields follow", 0), 0u)
      << reader.malformed_messages()[1];
}

TEST(CarmenLogReaderTest, StrictModeThrowsAtTheFirstMalformedLineAndCanReadOn) {
  std::istringstream in(kLog);
  CarmenLogReader reader(in, "run.log", {.strict = true});
  for (int i = 0; i < 3; ++i) ASSERT_TRUE(reader.next());
  try {
    reader.next();
    FAIL() << "no error for line 7";
  } catch (const LogParseError& error) {
    EXPECT_EQ(error.file(), "run.log");
    EXPECT_EQ(error.line(), 7);
  }
  EXPECT_THROW(reader.next(), LogParseError);  // line 10
  auto last = reader.next();
  ASSERT_TRUE(last);
  EXPECT_TRUE(std::holds_alternative<CarmenTruePos>(*last));
  EXPECT_EQ(reader.malformed_lines(), 2u);
}

TEST(CarmenLogReaderTest, KeepsOnlyTheFirstFewMessagesButCountsEveryMalformedLine) {
  std::string text;
  for (int i = 0; i < 25; ++i) text += "ODOM x\n";
  std::istringstream in(text);
  CarmenLogReader reader(in, "bad.log", {.kept_messages = 3});
  EXPECT_FALSE(reader.next());
  EXPECT_EQ(reader.malformed_lines(), 25u);
  ASSERT_EQ(reader.malformed_messages().size(), 3u);
  EXPECT_EQ(reader.malformed_messages()[2], "bad.log:3:6: odometry x: expected a number, got 'x'");
}

TEST(CarmenLogReaderTest, NamesABoundedNumberOfUnknownKeywords) {
  std::string text;
  const std::size_t distinct = CarmenLogReader::kMaxKeywords + 10;
  for (std::size_t i = 0; i < distinct; ++i) text += "KEY" + std::to_string(i) + " 1\n";
  text += "KEY0 2\n";
  std::istringstream in(text);
  CarmenLogReader reader(in, "many.log");
  EXPECT_FALSE(reader.next());
  EXPECT_EQ(reader.unknown_lines(), distinct + 1);
  EXPECT_EQ(reader.unknown_keywords().size(), CarmenLogReader::kMaxKeywords + 1);
  EXPECT_EQ(reader.unknown_keywords().at("..."), 10u);
  EXPECT_EQ(reader.unknown_keywords().at("KEY0"), 2u);
}

TEST(CarmenLogReaderTest, AnEmptyStreamHasNoRecords) {
  std::istringstream in("");
  CarmenLogReader reader(in, "empty.log");
  EXPECT_FALSE(reader.next());
  EXPECT_EQ(reader.line_number(), 0);
  EXPECT_EQ(reader.malformed_lines(), 0u);
}

}  // namespace carmen_log_reader_test
}  // namespace playerkit::log
