#include "core/device_table.hpp"

#include <algorithm>
#include <stdexcept>

namespace playerkit::core {

DeviceTable::~DeviceTable() {
  shutdown_all();
  while (!devices_.empty()) devices_.pop_back();
}

Device& DeviceTable::add(std::unique_ptr<Device> device) {
  const auto same_key = [&](const std::unique_ptr<Device>& d) { return d->key() == device->key(); };
  if (auto it = std::find_if(devices_.begin(), devices_.end(), same_key); it != devices_.end()) {
    *it = std::move(device);
    return **it;
  }
  devices_.push_back(std::move(device));
  return *devices_.back();
}

Device* DeviceTable::find(const DeviceKey& key) const {
  for (const auto& device : devices_) {
    if (device->key() == key) return device.get();
  }
  return nullptr;
}

std::vector<Device*> DeviceTable::on_port(std::uint16_t port) const {
  std::vector<Device*> found;
  for (const auto& device : devices_) {
    if (device->key().port == port) found.push_back(device.get());
  }
  return found;
}

const Device* DeviceTable::find_robot(std::string_view robot_name) const {
  for (const auto& device : devices_) {
    if (device->info().robot_name == robot_name) return device.get();
  }
  return nullptr;
}

std::vector<std::uint16_t> DeviceTable::ports() const {
  std::vector<std::uint16_t> ports;
  for (const auto& device : devices_) {
    if (std::find(ports.begin(), ports.end(), device->key().port) == ports.end()) {
      ports.push_back(device->key().port);
    }
  }
  return ports;
}

std::vector<Device*> DeviceTable::all() const {
  std::vector<Device*> all;
  all.reserve(devices_.size());
  for (const auto& device : devices_) all.push_back(device.get());
  return all;
}

void DeviceTable::prepare_all() {
  for (const auto& device : devices_) device->prepare();
}

void DeviceTable::start_alwayson() {
  for (const auto& device : devices_) {
    if (device->info().alwayson && !device->subscribe()) {
      throw std::runtime_error("alwayson device " + device->name() + " failed to set up");
    }
  }
}

void DeviceTable::shutdown_all() {
  for (auto it = devices_.rbegin(); it != devices_.rend(); ++it) (*it)->force_shutdown();
}

}  // namespace playerkit::core
