#include "config/driver_catalog.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "protocol/interfaces.hpp"

namespace playerkit::config {
namespace driver_catalog_test {

TEST(DriverCatalog, IsSortedWithoutDuplicates) {
  const auto drivers = player15_drivers();
  EXPECT_TRUE(std::is_sorted(drivers.begin(), drivers.end()));
  EXPECT_EQ(std::adjacent_find(drivers.begin(), drivers.end()), drivers.end());
  // 70 driver names of chapter 7, er1 under its source name too, 3 undocumented defaults.
  EXPECT_EQ(drivers.size(), 74u);
}

TEST(DriverCatalog, HoldsEveryDefaultDriver) {
  for (const protocol::InterfaceInfo& info : protocol::all_interfaces()) {
    if (info.default_driver.empty()) continue;
    EXPECT_TRUE(is_player15_driver(info.default_driver))
        << info.name << " -> " << info.default_driver;
  }
}

TEST(DriverCatalog, UsesConfigNamesNotManualHeadings) {
  for (const char* name :
       {"p2os_position", "p2os_cmucam", "sicklms200", "amcl", "passthrough", "readlog", "writelog",
        "lifomcom", "udpbroadcast", "cmucam2", "rflex_position", "rflex_done_is_not_a_driver"}) {
    const bool expected = std::string(name) != "rflex_done_is_not_a_driver";
    EXPECT_EQ(is_player15_driver(name), expected) << name;
  }
  for (const char* heading : {"p2os", "rflex", "lifo-mcom", "serviceadv-lsd", "waveaudio",
                              "adaptive_mcl", "gz camera", ""}) {
    EXPECT_FALSE(is_player15_driver(heading)) << heading;
  }
}

TEST(DriverCatalog, HoldsEachDriverFamilyOfChapter7) {
  for (const char* name : {"acts",
                           "acoustics",
                           "amtecpowercube",
                           "cmvision",
                           "er1_position",
                           "festival",
                           "fixedtones",
                           "flockofbirds",
                           "garminnmea",
                           "gz_camera",
                           "gz_gripper",
                           "gz_laser",
                           "gz_position",
                           "gz_position3d",
                           "gz_power",
                           "gz_ptz",
                           "gz_sonar",
                           "gz_truth",
                           "khepera_position",
                           "khepera_ir",
                           "lasercspace",
                           "laserbar",
                           "laserbarcode",
                           "laservisualbarcode",
                           "linuxwifi",
                           "mixer",
                           "nomad",
                           "nomad_position",
                           "nomad_sonar",
                           "p2os_aio",
                           "p2os_bumper",
                           "p2os_compass",
                           "p2os_dio",
                           "p2os_gripper",
                           "p2os_power",
                           "p2os_sonar",
                           "p2os_sound",
                           "ptu46",
                           "reb_position",
                           "reb_ir",
                           "reb_power",
                           "rflex_sonar",
                           "rflex_power",
                           "rflex_bumper",
                           "rflex_ir",
                           "rwi_bumper",
                           "rwi_laser",
                           "rwi_position",
                           "rwi_power",
                           "rwi_sonar",
                           "segwayrmp",
                           "service_adv_lsd",
                           "sickpls",
                           "sonyevid30",
                           "trogdor",
                           "upcbarcode",
                           "vfh",
                           "wave_audio",
                           "wavefront"}) {
    EXPECT_TRUE(is_player15_driver(name)) << name;
  }
}

}  // namespace driver_catalog_test
}  // namespace playerkit::config
