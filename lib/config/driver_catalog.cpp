#include "config/driver_catalog.hpp"

#include <algorithm>
#include <iterator>

namespace playerkit::config {
namespace {

// Manual section numbers in the comments; the families register one driver
// per interface they serve.
constexpr std::string_view kDrivers[] = {
    "acoustics",       // 7.2
    "acts",            // 7.1
    "amcl",            // 7.3
    "amtecpowercube",  // 7.4
    "camerav4l",       // default driver of camera (wire-format.md §4)
    "cmucam2",         // 7.5
    "cmvision",        // 7.6
    "er1",             // 7.7 (the name the 1.5 source registers)
    "er1_position",    // 7.7 (the manual's name)
    "festival",        // 7.8
    "fixedtones",      // 7.9
    "flockofbirds",    // 7.10
    "garminnmea",      // 7.11
    "gz_camera",       // 7.12 - 7.20: Gazebo
    "gz_gripper",
    "gz_laser",
    "gz_position",
    "gz_position3d",
    "gz_power",
    "gz_ptz",
    "gz_sonar",
    "gz_truth",
    "khepera_ir",  // 7.21
    "khepera_position",
    "laserbar",            // 7.23
    "laserbarcode",        // 7.24
    "lasercspace",         // 7.22
    "laservisualbarcode",  // 7.25
    "lifomcom",            // 7.26 "lifo-mcom"
    "linuxwifi",           // 7.27
    "mixer",               // 7.28
    "nomad",               // 7.29
    "nomad_position",
    "nomad_sonar",
    "p2os_aio",  // 7.30
    "p2os_bumper",
    "p2os_cmucam",
    "p2os_compass",
    "p2os_dio",
    "p2os_gripper",
    "p2os_position",
    "p2os_power",
    "p2os_sonar",
    "p2os_sound",
    "passthrough",  // 7.31
    "ptu46",        // 7.32
    "readlog",      // 7.36
    "reb_ir",       // 7.33
    "reb_position",
    "reb_power",
    "rflex_bumper",  // 7.34
    "rflex_ir",
    "rflex_position",
    "rflex_power",
    "rflex_sonar",
    "rwi_bumper",  // 7.35
    "rwi_laser",
    "rwi_position",
    "rwi_power",
    "rwi_sonar",
    "segwayrmp",         // 7.37
    "service_adv_lsd",   // 7.38 "serviceadv-lsd"
    "sicklms200",        // 7.39
    "sickpls",           // 7.40
    "sonyevid30",        // 7.41
    "stg_blinkenlight",  // default driver of blinkenlight (Stage)
    "stg_simulation",    // default driver of simulation (Stage)
    "trogdor",           // 7.42
    "udpbroadcast",      // 7.43
    "upcbarcode",        // 7.44
    "vfh",               // 7.45
    "wave_audio",        // 7.46 "waveaudio"
    "wavefront",         // 7.47
    "writelog",          // 7.48
};

}  // namespace

std::span<const std::string_view> player15_drivers() { return kDrivers; }

bool is_player15_driver(std::string_view name) {
  return std::binary_search(std::begin(kDrivers), std::end(kDrivers), name);
}

}  // namespace playerkit::config
