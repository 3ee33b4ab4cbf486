#include "log_tool.hpp"

#include <cerrno>
#include <cstring>
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

Output::Output(const std::string& path, std::ostream& standard_out) : path_(path), out_(&standard_out) {
  if (path == "-") {
    path_ = "stdout";
    return;
  }
  file_ = std::make_unique<std::ofstream>(path, std::ios::out | std::ios::trunc | std::ios::binary);
  if (!*file_) throw std::runtime_error("cannot write " + path + ": " + std::strerror(errno));
  out_ = file_.get();
}

void Output::check() const {
  if (!*out_) throw std::runtime_error("cannot write " + path_ + ": " + std::strerror(errno));
}

void Output::flush_and_check() {
  out_->flush();
  check();
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
