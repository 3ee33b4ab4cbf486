#include "log_tool.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "protocol/constants.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::plog {
namespace log_tool_test {

std::filesystem::path write_file(const std::string& name, const std::string& text) {
  const auto path = std::filesystem::path(::testing::TempDir()) / name;
  std::ofstream(path) << text;
  return path;
}

TEST(DetectLogFormat, TellsPlayerFromCarmenByContent) {
  EXPECT_EQ(detect_log_format(write_file("a.txt", "## Player version 1.5 \n## File version 0.0.0 \n")),
            LogFormat::kPlayer);
  EXPECT_EQ(detect_log_format(write_file("b.txt", "\n1086000000.250 host 6665 sync 00 1086000000.250 \n")),
            LogFormat::kPlayer);
  EXPECT_EQ(detect_log_format(write_file("c.txt", "# CARMEN Logfile\nODOM 0 0 0 0 0 0 1.0 h 1.0\n")),
            LogFormat::kCarmen);
  const auto radish = std::filesystem::path(PLAYERKIT_TEST_DATA_DIR) / "radish" / "intel-corrected.log.gz";
  EXPECT_EQ(detect_log_format(radish), LogFormat::kCarmen);
  EXPECT_THROW(detect_log_format(write_file("d.txt", "# only a comment\n")), std::runtime_error);
  EXPECT_THROW(detect_log_format(write_file("e.txt", "")), std::runtime_error);
  EXPECT_THROW(detect_log_format("/nonexistent/x.log"), std::runtime_error);
}

TEST(ParseDeviceList, NamesDevicesOrFails) {
  const auto devices = parse_device_list("laser:0,position,truth:2");
  ASSERT_EQ(devices.size(), 3u);
  EXPECT_EQ(devices[0], (protocol::DeviceAddress{protocol::kLaserCode, 0}));
  EXPECT_EQ(devices[1], (protocol::DeviceAddress{protocol::kPositionCode, 0}));
  EXPECT_EQ(devices[2], (protocol::DeviceAddress{protocol::kTruthCode, 2}));
  EXPECT_THROW(parse_device_list("laser:0,nosuch"), UsageError);
  EXPECT_THROW(parse_device_list(""), UsageError);
}

}  // namespace log_tool_test
}  // namespace playerkit::plog
