// record against a real server (tests/server/test_server.hpp) and from stdin.

#include "log_record.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <variant>

#include "log/log_input.hpp"
#include "log/text_log_reader.hpp"
#include "log_tool.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/messages/laser.hpp"
#include "server/test_server.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::plog {
namespace log_record_test {

std::vector<log::DataLine> data_lines(const std::string& text) {
  std::istringstream in(text);
  log::TextLogReader reader(in, "recorded", {.strict = true});
  std::vector<log::DataLine> lines;
  while (auto line = reader.next()) {
    if (auto* data = std::get_if<log::DataLine>(&*line)) lines.push_back(*data);
  }
  return lines;
}

TEST(Record, WritesWhatTheServerSends) {
  testing::TestServer server("laser:0 ( driver \"source\" )\n");
  protocol::LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 100;
  scan.range_res = 1;
  scan.range_count = 2;
  scan.ranges[0] = 1234;
  scan.ranges[1] = 4321;
  server.device("laser:0").publish(protocol::encode(scan), protocol::Timestamp{1086000000, 250000});

  RecordOptions options;
  parse_record_targets({"127.0.0.1:" + std::to_string(server.port()), "laser:0"}, options);
  options.output = "-";
  options.count = 1;
  std::istringstream in;
  std::ostringstream out, err;
  ASSERT_EQ(run_record(options, in, out, err, [] { return false; }), kExitOk) << err.str();
  EXPECT_EQ(out.str().rfind("## Player version 1.5 \n## File version 0.0.0 \n", 0), 0u);
  const auto lines = data_lines(out.str());
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(lines[0].message.timestamp(), (protocol::Timestamp{1086000000, 250000}));
  EXPECT_EQ(protocol::decode<protocol::LaserData>(lines[0].message.payload), scan);

  RecordOptions missing;
  parse_record_targets({"127.0.0.1:" + std::to_string(server.port()), "sonar:3"}, missing);
  missing.output = "-";
  EXPECT_EQ(run_record(missing, in, out, err, [] { return false; }), kExitFailure);
  EXPECT_NE(err.str().find("no device sonar:3"), std::string::npos) << err.str();
}

TEST(Record, FromStdinKeepsValidLinesAndSkipsBadOnes) {
  const std::string good = "1086000000.250 robot 6665 truth 00 1086000000.200 +1.000 +2.000 +0.500\n";
  std::istringstream in("## Player version 1.5 \n## File version 0.0.0 \n" + good + "garbage here\n" + good);
  RecordOptions options;
  parse_record_targets({"-"}, options);
  options.output = "-";
  std::ostringstream out, err;
  ASSERT_EQ(run_record(options, in, out, err, [] { return false; }), kExitOk);
  EXPECT_EQ(out.str(), "## Player version 1.5 \n## File version 0.0.0 \n" + good + good);
  EXPECT_NE(err.str().find("stdin:4:"), std::string::npos) << err.str();

  std::istringstream bad("garbage\n");
  options.strict = true;
  EXPECT_EQ(run_record(options, bad, out, err, [] { return false; }), kExitFailure);
}

std::string file_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(Record, ARecordingThatCannotStartLeavesAnOlderFileAlone) {
  testing::TestServer server("laser:0 ( driver \"source\" )\n");
  testing::ScratchDirectory scratch("log_record_test");
  const auto older = scratch.write("run.log", "yesterday's recording\n");
  RecordOptions options;
  parse_record_targets({"127.0.0.1:" + std::to_string(server.port()), "sonar:3"}, options);
  options.output = older.string();
  std::istringstream in;
  std::ostringstream out, err;
  EXPECT_EQ(run_record(options, in, out, err, [] { return false; }), kExitFailure);
  EXPECT_EQ(file_text(older), "yesterday's recording\n");
}

TEST(Record, ADotGzOutputIsRecordedGzipAndReadsBack) {
  testing::TestServer server("laser:0 ( driver \"source\" )\n");
  protocol::LaserData scan;
  scan.range_count = 1;
  scan.range_res = 1;
  scan.ranges[0] = 777;
  server.device("laser:0").publish(protocol::encode(scan), protocol::Timestamp{1086000000, 0});
  testing::ScratchDirectory scratch("log_record_test");
  RecordOptions options;
  parse_record_targets({"127.0.0.1:" + std::to_string(server.port()), "laser:0"}, options);
  options.output = scratch.file("run.log.gz").string();
  options.count = 1;
  std::istringstream in;
  std::ostringstream out, err;
  ASSERT_EQ(run_record(options, in, out, err, [] { return false; }), kExitOk) << err.str();
  EXPECT_TRUE(file_text(options.output).starts_with("\x1f\x8b"));
  auto log = log::open_log_input(options.output);
  const std::string text{std::istreambuf_iterator<char>(*log), std::istreambuf_iterator<char>()};
  EXPECT_FALSE(log->error());
  const auto lines = data_lines(text);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_EQ(protocol::decode<protocol::LaserData>(lines[0].message.payload).ranges[0], 777);
}

TEST(Record, TargetsAreCheckedAsUsage) {
  RecordOptions options;
  EXPECT_THROW(parse_record_targets({"localhost:7000"}, options), UsageError);
  RecordOptions other;
  EXPECT_THROW(parse_record_targets({"laser:0", "nosuch"}, other), UsageError);
}

}  // namespace log_record_test
}  // namespace playerkit::plog
