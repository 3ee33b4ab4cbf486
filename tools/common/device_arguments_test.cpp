#include "device_arguments.hpp"

#include <gtest/gtest.h>

#include "exit_status.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::tools {
namespace device_arguments_test {

std::string usage_error_of(const std::vector<std::string>& words) {
  try {
    parse_device_arguments(words);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "";
}

TEST(DeviceArguments, NamesIndicesAndCodes) {
  const auto devices = parse_device_arguments({"laser:0", "position", "6:1"});
  ASSERT_EQ(devices.size(), 3u);
  EXPECT_EQ(devices[0], (protocol::DeviceAddress{protocol::kLaserCode, 0}));
  EXPECT_EQ(devices[1], (protocol::DeviceAddress{protocol::kPositionCode, 0}));
  EXPECT_EQ(devices[2], (protocol::DeviceAddress{6, 1}));
  EXPECT_TRUE(parse_device_arguments({}).empty());
}

TEST(DeviceArguments, ANonDeviceOrADeviceNamedTwiceIsAUsageError) {
  EXPECT_EQ(usage_error_of({"lazer:0"}), "'lazer:0' is not a device: write interface[:index], e.g. laser:0 or position");
  EXPECT_EQ(usage_error_of({"laser:0", "6:0"}), "device laser:0 is named twice");
}

}  // namespace device_arguments_test
}  // namespace playerkit::tools
