#include "families/p2os/driver/p2os_role.hpp"

namespace playerkit::drivers::p2os {

std::string_view driver_name(P2osRole role) {
  switch (role) {
    case P2osRole::position: return "p2os_position";
    case P2osRole::sonar: return "p2os_sonar";
    case P2osRole::gripper: return "p2os_gripper";
    case P2osRole::power: return "p2os_power";
    case P2osRole::bumper: return "p2os_bumper";
    case P2osRole::aio: return "p2os_aio";
    case P2osRole::dio: return "p2os_dio";
    case P2osRole::cmucam: return "p2os_cmucam";
    case P2osRole::compass: return "p2os_compass";
    case P2osRole::gyro: return "p2os_gyro";
    case P2osRole::sound: return "p2os_sound";
  }
  return "p2os";
}

}  // namespace playerkit::drivers::p2os
