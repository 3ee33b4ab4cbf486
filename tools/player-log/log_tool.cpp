#include "log_tool.hpp"

#include <sstream>

namespace playerkit::plog {

std::vector<protocol::DeviceAddress> parse_device_list(const std::string& text) {
  std::vector<protocol::DeviceAddress> devices;
  std::istringstream items(text);
  std::string item;
  while (std::getline(items, item, ',')) {
    const auto device = protocol::parse_device_address(item);
    if (!device) throw UsageError("--devices: '" + item + "' is not a device (laser:0, position, 6:1)");
    devices.push_back(*device);
  }
  if (devices.empty()) throw UsageError("--devices: no device named");
  return devices;
}

void Progress::show() {
  const auto now = std::chrono::steady_clock::now();
  if (shown_ && now - last_ < std::chrono::milliseconds(250)) return;
  last_ = now;
  shown_ = true;
  err_ << "\rplayer-log: " << count_ << " messages" << std::flush;
}

Progress::~Progress() {
  if (shown_) err_ << "\r\033[K" << std::flush;
}

}  // namespace playerkit::plog
