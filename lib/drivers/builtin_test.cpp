#include "drivers/builtin.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "drivers/test_support.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::drivers {
namespace builtin_test {

using protocol::Access;

TEST(BuiltinDrivers, RegistersEveryDriverSortedByName) {
  core::DriverRegistry registry;
  register_builtin_drivers(registry);
  std::vector<std::string> names;
  for (const core::DriverSpec* spec : registry.all()) {
    names.push_back(spec->name);
    EXPECT_FALSE(spec->summary.empty()) << spec->name;
    EXPECT_EQ(spec->summary.find('\n'), std::string::npos) << spec->name;  // one line
    EXPECT_TRUE(static_cast<bool>(spec->factory)) << spec->name;
    EXPECT_GE(spec->limits.request_queue, 1u) << spec->name;
    EXPECT_FALSE(spec->family.empty()) << spec->name;  // generated from the families built
  }
  // The list is generated from the families built (builtin_drivers.cpp.in),
  // so the expectation is derived, not written out again: every family built
  // gives drivers, and no driver comes from a family left out. Each family's
  // own tests check its drivers' names (p2os_options_test, sick_driver_settings_test).
  std::set<std::string> built;
  std::stringstream built_text(PLAYERKIT_BUILT_DRIVER_FAMILIES);
  for (std::string family; std::getline(built_text, family, ',');) built.insert(family);
  std::set<std::string> registered;
  for (const core::DriverSpec* spec : registry.all()) registered.insert(spec->family);
  EXPECT_EQ(registered, built);
  EXPECT_TRUE(std::is_sorted(names.begin(), names.end()));
  EXPECT_EQ(std::adjacent_find(names.begin(), names.end()), names.end()) << "a name registered twice";
}

TEST(BuiltinDrivers, EachDriverNamesItsFamily) {
  core::DriverRegistry registry;
  register_builtin_drivers(registry);
  ASSERT_NE(registry.find("readlog"), nullptr);
  EXPECT_EQ(registry.find("readlog")->family, "logfile");
  EXPECT_EQ(registry.find("writelog")->family, "logfile");
  EXPECT_EQ(registry.find("amcl")->family, "amcl");
  EXPECT_EQ(registry.find("lifomcom")->family, "mcom");
}

TEST(BuiltinDrivers, InterfacesAndAccessAsIn15) {
  core::DriverRegistry registry;
  register_builtin_drivers(registry);
  struct Expected {
    const char* name;
    std::uint16_t interface;
    Access access;
  };
  for (const Expected& expected : {Expected{"null", protocol::kNullCode, Access::kRead},
                                   Expected{"lifomcom", protocol::kMcomCode, Access::kAll},
                                   Expected{"udpbroadcast", protocol::kCommsCode, Access::kAll},
                                   Expected{"writelog", protocol::kNullCode, Access::kRead},
                                   Expected{"amcl", protocol::kLocalizeCode, Access::kRead}}) {
    const core::DriverSpec* spec = registry.find(expected.name);
    ASSERT_NE(spec, nullptr) << expected.name;
    EXPECT_EQ(spec->interfaces, (std::vector<std::uint16_t>{expected.interface})) << expected.name;
    EXPECT_EQ(spec->access, expected.access) << expected.name;
  }
}

TEST(BuiltinDrivers, OneConfigFileMakesADeviceOfEach) {
  testing::BuiltinDevices builtin;
  builtin.load(
      "null ( driver \"null\" )\n"
      "mcom ( driver \"lifomcom\" )\n"
      "comms ( driver \"udpbroadcast\" port 6013 )\n");  // never subscribed: no socket
  ASSERT_EQ(builtin.devices.size(), 3u);
  EXPECT_EQ(builtin.device(protocol::kNullCode).info().driver_name, "null");
  EXPECT_EQ(builtin.device(protocol::kMcomCode).info().driver_name, "lifomcom");
  EXPECT_EQ(builtin.device(protocol::kMcomCode).info().limits.request_queue, 20u);
  EXPECT_EQ(builtin.device(protocol::kCommsCode).info().driver_name, "udpbroadcast");
  EXPECT_EQ(builtin.device(protocol::kCommsCode).info().access, Access::kAll);
}

TEST(BuiltinDrivers, DefaultDriversOfMcomAndCommsAreBuiltIn) {
  // Sections without `driver` get 1.5's default for the interface.
  testing::BuiltinDevices builtin;
  builtin.load("mcom:0 ()\ncomms:0 ()\n");
  EXPECT_EQ(builtin.device(protocol::kMcomCode).info().driver_name, "lifomcom");
  EXPECT_EQ(builtin.device(protocol::kCommsCode).info().driver_name, "udpbroadcast");
}

}  // namespace builtin_test
}  // namespace playerkit::drivers
