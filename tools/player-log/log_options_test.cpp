#include "log_options.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace log_options_test {

using namespace playerkit::plog;  // NOLINT: inside the test's own namespace
namespace protocol = playerkit::protocol;

template <typename Make, typename CommandLine>
std::string usage_error(Make make, const CommandLine& command_line) {
  try {
    (void)make(command_line);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(LogOptions, ConvertFlagsReachTheOptions) {
  ConvertCommandLine command_line;
  command_line.input = "in.log";
  command_line.output = "out.csv";
  command_line.to = "csv";
  command_line.devices = "laser:0,position";
  command_line.si = true;
  command_line.strict = true;
  const auto options = make_convert_options(command_line);
  EXPECT_EQ(options.input, "in.log");
  EXPECT_EQ(options.output, "out.csv");
  ASSERT_TRUE(options.to.has_value());
  EXPECT_EQ(*options.to, ConvertTarget::kCsv);
  ASSERT_EQ(options.devices.size(), 2u);
  EXPECT_EQ(protocol::to_string(options.devices[1]), protocol::to_string(*protocol::parse_device_address("position:0")));
  EXPECT_TRUE(options.si);
  EXPECT_TRUE(options.strict);
}

TEST(LogOptions, ConvertDefaultsLeaveTargetAndDevicesOpen) {
  ConvertCommandLine command_line;
  command_line.input = "in.log";
  command_line.output = "-";
  const auto options = make_convert_options(command_line);
  EXPECT_FALSE(options.to.has_value());
  EXPECT_TRUE(options.devices.empty());
}

TEST(LogOptions, ConvertRefusesUnknownTargetsAndDevices) {
  ConvertCommandLine command_line;
  command_line.to = "xml";
  EXPECT_NE(usage_error(make_convert_options, command_line), "");
  command_line.to = "";
  command_line.devices = "laser:x";
  EXPECT_NE(usage_error(make_convert_options, command_line), "");
}

TEST(LogOptions, CutWindowMustNotEndBeforeItStarts) {
  CutCommandLine command_line;
  command_line.start = 20;
  command_line.end = 10;
  EXPECT_EQ(usage_error(make_cut_options, command_line), "--end is before --start");
  command_line.end = 20;
  const auto options = make_cut_options(command_line);
  EXPECT_EQ(options.start, 20.0);
  EXPECT_EQ(options.end, 20.0);
  command_line.start.reset();
  EXPECT_EQ(usage_error(make_cut_options, command_line), "");
}

TEST(LogOptions, RecordTargetsAndLimits) {
  RecordCommandLine command_line;
  command_line.targets = {"-"};
  command_line.output = "run.log";
  command_line.count = 100;
  command_line.duration = 60;
  command_line.timeout = 2;
  auto options = make_record_options(command_line);
  EXPECT_TRUE(options.from_stdin);
  EXPECT_EQ(options.count, 100u);
  EXPECT_EQ(options.duration, 60.0);
  EXPECT_DOUBLE_EQ(options.timeout, 2.0);

  command_line.targets = {"laser:0", "position:0"};
  options = make_record_options(command_line);
  EXPECT_FALSE(options.from_stdin);
  EXPECT_EQ(options.devices.size(), 2u);

  command_line.duration = 0;
  EXPECT_EQ(usage_error(make_record_options, command_line), "--duration must be > 0");
  command_line.duration.reset();
  command_line.timeout = 0;
  EXPECT_EQ(usage_error(make_record_options, command_line), "--timeout must be > 0");
  command_line.timeout = 5;
  command_line.targets = {"laser:0", "nonsense!"};
  EXPECT_NE(usage_error(make_record_options, command_line), "");
}

TEST(LogOptions, RecordFrequencyIsTheServersWholeHertz) {
  RecordCommandLine command_line;
  command_line.targets = {"laser:0"};
  command_line.output = "run.log";
  EXPECT_FALSE(make_record_options(command_line).frequency.has_value());
  command_line.frequency = 100;
  EXPECT_EQ(make_record_options(command_line).frequency, std::uint16_t{100});
  for (const double bad : {0.0, 2.5, 65536.0, -1.0}) {
    command_line.frequency = bad;
    EXPECT_EQ(usage_error(make_record_options, command_line),
              "--frequency is the server's data frequency: a whole number of Hz, 1 to 65535")
        << bad;
  }
  command_line.frequency = 40;
  command_line.targets = {"-"};
  EXPECT_EQ(usage_error(make_record_options, command_line),
            "--frequency is for recording from a server, not from stdin");
}

TEST(LogOptions, ReplayFlagsReachTheOptions) {
  ReplayCommandLine command_line;
  command_line.input = "run.log";
  command_line.port = 0;
  command_line.bind_address = "127.0.0.1";
  command_line.rate = 2;
  command_line.loop = true;
  command_line.burst = true;
  command_line.start = 5;
  command_line.duration = 10;
  command_line.devices = "laser:0";
  command_line.quiet = true;
  const auto options = make_replay_options(command_line);
  EXPECT_EQ(options.input, "run.log");
  EXPECT_EQ(options.port, 0);
  EXPECT_EQ(options.bind_address, "127.0.0.1");
  EXPECT_DOUBLE_EQ(options.rate, 2.0);
  EXPECT_TRUE(options.loop);
  EXPECT_TRUE(options.burst);
  EXPECT_DOUBLE_EQ(options.start, 5.0);
  EXPECT_EQ(options.duration, 10.0);
  EXPECT_EQ(options.devices.size(), 1u);
  EXPECT_EQ(options.log_level, playerkit::core::LogLevel::kError);
  EXPECT_EQ(make_replay_options(ReplayCommandLine{}).log_level, playerkit::core::LogLevel::kInfo);
}

TEST(LogOptions, ReplayRefusesImpossibleTimes) {
  ReplayCommandLine command_line;
  command_line.rate = 0;
  EXPECT_EQ(usage_error(make_replay_options, command_line), "--rate must be above 0 and below 1000000");
  command_line.rate = 1e6;
  EXPECT_EQ(usage_error(make_replay_options, command_line), "--rate must be above 0 and below 1000000");
  command_line.rate = 1;
  command_line.start = -1;
  EXPECT_EQ(usage_error(make_replay_options, command_line), "--start must be 0 or more");
  command_line.start = 0;
  command_line.duration = 0;
  EXPECT_EQ(usage_error(make_replay_options, command_line), "--duration must be > 0");
  command_line.duration = std::nan("");
  EXPECT_EQ(usage_error(make_replay_options, command_line), "--duration must be > 0");
}

}  // namespace log_options_test
