#include "device_arguments.hpp"

#include <algorithm>

#include "exit_status.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::tools {

std::vector<protocol::DeviceAddress> parse_device_arguments(const std::vector<std::string>& words) {
  std::vector<protocol::DeviceAddress> devices;
  for (const auto& word : words) {
    const auto device = protocol::parse_device_address(word);
    if (!device) {
      throw UsageError("'" + word + "' is not a device: write interface[:index], e.g. laser:0 or position");
    }
    if (std::find(devices.begin(), devices.end(), *device) != devices.end()) {
      throw UsageError("device " + protocol::to_string(*device) + " is named twice");
    }
    devices.push_back(*device);
  }
  return devices;
}

}  // namespace playerkit::tools
