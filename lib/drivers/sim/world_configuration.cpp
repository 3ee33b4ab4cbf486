#include "drivers/sim/world_configuration.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <string_view>

#include "protocol/interfaces.hpp"
#include "text/printable.hpp"

namespace playerkit::drivers::sim {

namespace {

// The world file words the simulated drivers answer to (sim_drivers.cpp).
constexpr std::array<std::string_view, 14> kTypeWords{
    "position", "omniposition", "laser", "ranger",  "sonar", "fiducialfinder", "lbd",
    "fiducial", "blobfinder",   "vision", "ptz",    "gripper", "power",        "truth"};

std::string_view stage13_word(std::uint16_t interface) {
  switch (interface) {
    case protocol::kPositionCode: return "position";
    case protocol::kLaserCode: return "laser";
    case protocol::kSonarCode: return "sonar";
    case protocol::kFiducialCode: return "fiducialfinder";
    case protocol::kBlobfinderCode: return "blobfinder";
    case protocol::kPtzCode: return "ptz";
    case protocol::kGripperCode: return "gripper";
    case protocol::kPowerCode: return "power";
    case protocol::kTruthCode: return "truth";
    default: return "";
  }
}

}  // namespace

std::string world_device_driver(const playerkit::sim::worldfile::SimDevice& device) {
  if (std::find(kTypeWords.begin(), kTypeWords.end(), device.driver_name) != kTypeWords.end()) {
    return device.driver_name;
  }
  return std::string(stage13_word(device.interface_code));
}

std::string world_configuration(const playerkit::sim::World& world,
                                const std::vector<playerkit::sim::worldfile::SimDevice>& devices,
                                std::uint16_t default_port) {
  std::string text;
  std::uint16_t port = default_port;
  for (const auto& device : devices) {
    const std::string driver = world_device_driver(device);
    if (driver.empty()) continue;  // an interface no simulated driver serves
    const std::string& name = world.spec(device.model).name;
    if (name.find_first_of("\"\r\n") != std::string::npos) {
      throw std::runtime_error("model name \"" + text::excerpt(name) + "\" cannot be written in a configuration");
    }
    if (device.port != port) {
      port = device.port;
      text += "robot:" + std::to_string(port) + " ( )\n";
    }
    text += protocol::interface_name(device.interface_code) + ":" + std::to_string(device.index) + " ( driver \"" +
            driver + "\" model \"" + name + "\" )\n";
  }
  // World files have no simulation device. Always on: a command is acted on
  // even when its sender has gone.
  if (port != default_port) text += "robot:" + std::to_string(default_port) + " ( )\n";
  text += "simulation:0 ( driver \"simulation\" alwayson 1 )\n";
  return text;
}

}  // namespace playerkit::drivers::sim
