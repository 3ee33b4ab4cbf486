#include "protocol/interfaces.hpp"

#include <gtest/gtest.h>

#include "protocol/device_address.hpp"

namespace playerkit::protocol {
namespace interfaces_test {

TEST(Interfaces, HeaderCodesWinOverTheManual) {
  EXPECT_EQ(find_interface("null")->code, 256);
  EXPECT_EQ(find_interface("camera")->code, 40);
  EXPECT_EQ(find_interface("nomad")->code, 34);
  EXPECT_EQ(find_interface(std::uint16_t{6})->name, "laser");
  EXPECT_EQ(find_interface(std::uint16_t{19}), nullptr);
  EXPECT_EQ(all_interfaces().size(), 35u);
}

TEST(Interfaces, DefaultDrivers) {
  EXPECT_EQ(find_interface("laser")->default_driver, "sicklms200");
  EXPECT_EQ(find_interface("null")->default_driver, "writelog");
  EXPECT_EQ(find_interface("localize")->default_driver, "amcl");
  EXPECT_EQ(find_interface("truth")->default_driver, "passthrough");
  EXPECT_TRUE(find_interface("player")->default_driver.empty());
  EXPECT_TRUE(find_interface("idar")->default_driver.empty());
}

TEST(DeviceAddress, ParsesNamesIndicesAndCodes) {
  EXPECT_EQ(parse_device_address("laser:0"), (DeviceAddress{kLaserCode, 0}));
  EXPECT_EQ(parse_device_address("position"), (DeviceAddress{kPositionCode, 0}));
  EXPECT_EQ(parse_device_address("sonar:12"), (DeviceAddress{kSonarCode, 12}));
  EXPECT_EQ(parse_device_address("6:1"), (DeviceAddress{kLaserCode, 1}));
  EXPECT_FALSE(parse_device_address("lazer:0"));
  EXPECT_FALSE(parse_device_address("laser:"));
  EXPECT_FALSE(parse_device_address("laser:x"));
  EXPECT_FALSE(parse_device_address("laser:70000"));
  EXPECT_FALSE(parse_device_address("laser:+1"));
  EXPECT_EQ(to_string(DeviceAddress{kLaserCode, 2}), "laser:2");
  EXPECT_EQ(to_string(DeviceAddress{99, 0}), "99:0");
}

}  // namespace interfaces_test
}  // namespace playerkit::protocol
