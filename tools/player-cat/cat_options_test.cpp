#include "cat_options.hpp"

#include <gtest/gtest.h>

#include "protocol/interfaces.hpp"

namespace playerkit::cat {
namespace cat_options_test {

CommandLine with_targets(std::vector<std::string> targets) {
  CommandLine command_line;
  command_line.targets = std::move(targets);
  return command_line;
}

// The UsageError's message, or "" when there is none.
std::string usage_error(const CommandLine& command_line) {
  try {
    make_cat_options(command_line);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(CatOptionsTest, DefaultsToLocalhostPushNewText) {
  const auto options = make_cat_options(with_targets({"laser:0", "position"}));
  EXPECT_EQ(options.server, (client::ServerEndpoint{"localhost", 6665}));
  const std::vector<protocol::DeviceAddress> expected{{protocol::kLaserCode, 0},
                                                      {protocol::kPositionCode, 0}};
  EXPECT_EQ(options.devices, expected);
  EXPECT_EQ(options.format, OutputFormat::kText);
  EXPECT_EQ(options.mode, protocol::DataMode::kPushNew);
  EXPECT_EQ(options.time_style, TimeStyle::kAbsolute);
  EXPECT_FALSE(options.count);
  EXPECT_FALSE(options.pull_mode());
}

TEST(CatOptionsTest, TakesAServerFirst) {
  const auto options = make_cat_options(with_targets({"robot1:7000", "laser:1"}));
  EXPECT_EQ(options.server, (client::ServerEndpoint{"robot1", 7000}));
  EXPECT_EQ(options.devices, (std::vector<protocol::DeviceAddress>{{protocol::kLaserCode, 1}}));
}

TEST(CatOptionsTest, ConvertsEveryFlag) {
  auto command_line = with_targets({"power"});
  command_line.format = "json";
  command_line.count = 5;
  command_line.once = true;
  command_line.duration = 2.5;
  command_line.fields = {"charge", "a.b.0"};
  command_line.mode = "pull-all";
  command_line.rate = 0.5;
  command_line.key = "secret";
  command_line.timestamps = "z";
  command_line.si = true;
  command_line.timeout = 1.5;
  const auto options = make_cat_options(command_line);
  EXPECT_EQ(options.format, OutputFormat::kJson);
  EXPECT_EQ(options.count, 5u);
  EXPECT_TRUE(options.once);
  EXPECT_EQ(options.duration, 2.5);
  ASSERT_EQ(options.fields.size(), 2u);
  EXPECT_EQ(options.fields[1].segments(), (std::vector<std::string>{"a", "b", "0"}));
  EXPECT_EQ(options.mode, protocol::DataMode::kPullAll);
  EXPECT_TRUE(options.pull_mode());
  EXPECT_EQ(options.rate, 0.5);
  EXPECT_EQ(options.key, "secret");
  EXPECT_EQ(options.time_style, TimeStyle::kZero);
  EXPECT_TRUE(options.si);
  EXPECT_EQ(options.timeout, 1.5);
}

TEST(CatOptionsTest, DevicesAreRequiredExceptForList) {
  EXPECT_NE(usage_error(with_targets({})).find("name at least one device"), std::string::npos);
  EXPECT_NE(usage_error(with_targets({"robot1:7000"})).find("name at least one device"), std::string::npos);
  auto list = with_targets({"robot1:7000"});
  list.list = true;
  EXPECT_TRUE(make_cat_options(list).list);
  list.targets.push_back("laser");
  EXPECT_NE(usage_error(list).find("--list"), std::string::npos);
}

TEST(CatOptionsTest, BadDevicesAndServersAreNamed) {
  EXPECT_NE(usage_error(with_targets({"laser", "lazer:0"})).find("'lazer:0' is not a device"),
            std::string::npos);
  EXPECT_NE(usage_error(with_targets({"laser:x"})).find("'laser:x' is neither a device"), std::string::npos);
  EXPECT_NE(usage_error(with_targets({"laser:0", "laser"})).find("laser:0 is named twice"),
            std::string::npos);
}

TEST(CatOptionsTest, BadValuesAreNamed) {
  const auto expect_error = [](auto change, const std::string& text) {
    auto command_line = with_targets({"laser"});
    change(command_line);
    const auto error = usage_error(command_line);
    EXPECT_NE(error.find(text), std::string::npos) << "got: '" << error << "', wanted: " << text;
  };
  expect_error([](CommandLine& c) { c.format = "xml"; }, "--format 'xml'");
  expect_error([](CommandLine& c) { c.count = 0; }, "--count");
  expect_error([](CommandLine& c) { c.duration = 0.0; }, "--duration");
  expect_error([](CommandLine& c) { c.duration = -1.0; }, "--duration");
  expect_error([](CommandLine& c) { c.fields = {"a..b"}; }, "--field");
  expect_error([](CommandLine& c) { c.mode = "push"; }, "--mode 'push'");
  expect_error([](CommandLine& c) { c.rate = 0.0; }, "--rate");
  expect_error([](CommandLine& c) { c.rate = 2.5; }, "whole number");  // push: server frequency
  expect_error([](CommandLine& c) { c.rate = 70000.0; }, "65535");
  expect_error([](CommandLine& c) { c.key = ""; }, "--key");
  expect_error([](CommandLine& c) { c.timestamps = "x"; }, "-t 'x'");
  expect_error([](CommandLine& c) { c.timeout = 0.0; }, "--timeout");
}

TEST(CatOptionsTest, PullModesTakeFractionalRates) {
  auto command_line = with_targets({"laser"});
  command_line.mode = "pull-new";
  command_line.rate = 2.5;
  EXPECT_EQ(make_cat_options(command_line).rate, 2.5);
}

TEST(CatOptionsTest, CsvOnStdoutTakesOneDeviceCsvDirSeveral) {
  auto command_line = with_targets({"laser", "power"});
  command_line.format = "csv";
  const auto error = usage_error(command_line);
  EXPECT_NE(error.find("CSV on stdout takes one device"), std::string::npos) << error;
  EXPECT_NE(error.find("--csv-dir DIR"), std::string::npos) << error;
  command_line.csv_dir = "out";
  const auto options = make_cat_options(command_line);
  EXPECT_EQ(options.csv_dir, std::filesystem::path("out"));
  command_line.format = "json";
  EXPECT_NE(usage_error(command_line).find("--csv-dir writes CSV files"), std::string::npos);
}

TEST(CatOptionsTest, LogLinesTakeNoFieldsUnitsOrRelativeTimes) {
  auto command_line = with_targets({"laser"});
  command_line.format = "log";
  EXPECT_EQ(make_cat_options(command_line).format, OutputFormat::kLog);
  command_line.fields = {"ranges.0"};
  EXPECT_NE(usage_error(command_line).find("--field does not apply"), std::string::npos);
  command_line.fields.clear();
  command_line.si = true;
  EXPECT_NE(usage_error(command_line).find("--si does not apply"), std::string::npos);
  command_line.si = false;
  command_line.timestamps = "d";
  EXPECT_NE(usage_error(command_line).find("-t d and -t z"), std::string::npos);
}

TEST(CatOptionsTest, CsvFileNames) {
  EXPECT_EQ(csv_file_name({protocol::kLaserCode, 0}), "laser_0.csv");
  EXPECT_EQ(csv_file_name({protocol::kPowerCode, 12}), "power_12.csv");
}

}  // namespace cat_options_test
}  // namespace playerkit::cat
