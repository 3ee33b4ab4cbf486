#include "run_options.hpp"

#include <gtest/gtest.h>

#include "protocol/interfaces.hpp"

namespace playerkit::player_drivers {
namespace run_options_test {

std::string usage_error_of(const RunCommandLine& line) {
  try {
    make_run_options(line);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

RunCommandLine line_of(std::vector<std::string> words) {
  RunCommandLine line;
  line.words = std::move(words);
  return line;
}

TEST(RunOptions, NameThenOptions) {
  auto line = line_of({"sicklms200", "port=/tmp/laser", "rate=38400"});
  line.plugins = {"x.so"};
  const RunOptions options = make_run_options(line);
  EXPECT_EQ(options.plan.name, "sicklms200");
  EXPECT_EQ(options.plan.options, (std::vector<OptionAssignment>{{"port", "/tmp/laser"}, {"rate", "38400"}}));
  EXPECT_EQ(options.plugins, std::vector<std::string>{"x.so"});
  EXPECT_EQ(options.bind_address, "127.0.0.1");
  EXPECT_FALSE(options.serve_port);
  EXPECT_TRUE(options.cat_line.targets.empty());
}

TEST(RunOptions, NeedsANameFirst) {
  EXPECT_EQ(usage_error_of(line_of({})), "run: name a driver (player-drivers list shows them) or a family of drivers served together");
  EXPECT_EQ(usage_error_of(line_of({"port=/dev/ttyS0", "sicklms200"})),
            "run: the driver's name comes first, then its OPTION=VALUE pairs (got 'port=/dev/ttyS0')");
  EXPECT_EQ(usage_error_of(line_of({"null", "fast"})), "'fast' is not OPTION=VALUE (e.g. port=/dev/ttyUSB0)");
}

TEST(RunOptions, PlayerCatsFlagsAreCheckedAsPlayerCatChecksThem) {
  auto line = line_of({"null"});
  line.format = "xml";
  EXPECT_EQ(usage_error_of(line), "--format 'xml': expected text, json, csv or log");
  line = line_of({"null"});
  line.duration = -1;
  EXPECT_EQ(usage_error_of(line), "--duration must be a positive number of seconds");
  line = line_of({"null"});
  line.format = "log";
  line.si = true;
  EXPECT_EQ(usage_error_of(line), "--si does not apply to --format log (log lines have units of their own)");
  line = line_of({"null"});
  line.fields = {"ranges..0"};
  EXPECT_NE(usage_error_of(line).find("--field"), std::string::npos);
}

TEST(RunOptions, Device) {
  auto line = line_of({"readlog"});
  line.device = "laser:1";
  EXPECT_EQ(make_run_options(line).device, (protocol::DeviceAddress{protocol::kLaserCode, 1}));
  line.device = "lazer";
  EXPECT_EQ(usage_error_of(line), "--device 'lazer' is not a device: write interface[:index], e.g. laser:0");
}

TEST(RunOptions, RequestsAndStdin) {
  auto line = line_of({"lifomcom"});
  line.request = {"push", "channel=news"};
  EXPECT_EQ(make_run_options(line).request, (std::vector<std::string>{"push", "channel=news"}));
  line.from_stdin = true;
  EXPECT_EQ(usage_error_of(line), "--req sends one request, --stdin many: choose one");
  line.from_stdin = false;
  line.count = 3;
  EXPECT_EQ(usage_error_of(line), "--req sends one request, prints the reply and exits: -n and --duration do not apply");
  line = line_of({"lifomcom"});
  line.request = {"channel=news"};
  EXPECT_EQ(usage_error_of(line), "--req: name the request first (e.g. --req get-geom), then FIELD=VALUE pairs");
}

TEST(RunOptions, ServeBindsEverywhereUnlessToldWhere) {
  auto line = line_of({"null"});
  line.serve_port = 7000;
  RunOptions options = make_run_options(line);
  EXPECT_EQ(options.serve_port, 7000);
  EXPECT_EQ(options.bind_address, "0.0.0.0");
  line.bind = "127.0.0.1";
  EXPECT_EQ(make_run_options(line).bind_address, "127.0.0.1");
  line.serve_port = 70000;
  EXPECT_EQ(usage_error_of(line), "--serve: a port number is 0 (any free port) to 65535");
  line = line_of({"null"});
  line.bind = "127.0.0.1";
  EXPECT_EQ(usage_error_of(line), "--bind says where --serve listens: it needs --serve PORT");
}

TEST(RunOptions, RecordStatsTrace) {
  auto line = line_of({"null"});
  line.record = "run.log";
  line.stats = true;
  line.trace = true;
  const RunOptions options = make_run_options(line);
  EXPECT_EQ(options.plan.record_file, "run.log");
  EXPECT_TRUE(options.stats);
  EXPECT_TRUE(options.trace);
}

}  // namespace run_options_test
}  // namespace playerkit::player_drivers
