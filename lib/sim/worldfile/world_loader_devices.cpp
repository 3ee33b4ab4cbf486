#include "sim/worldfile/world_loader_devices.hpp"

#include <map>
#include <tuple>

#include "protocol/interfaces.hpp"
#include "sim/worldfile/worldfile_error.hpp"

namespace playerkit::sim::worldfile {
namespace {

using DeviceKey = std::tuple<std::uint16_t, std::uint16_t, int>;  // port, interface, index

class IndexBook {
 public:
  // The device already at `key`, if any.
  const DeviceEntity* holder(const DeviceKey& key) const {
    const auto found = taken_.find(key);
    return found == taken_.end() ? nullptr : found->second;
  }
  void take(const DeviceKey& key, const DeviceEntity& device) { taken_.emplace(key, &device); }
  int lowest_free(std::uint16_t port, std::uint16_t code, int from = 0) const {
    int index = from;
    while (holder({port, code, index}) != nullptr) ++index;
    return index;
  }

 private:
  std::map<DeviceKey, const DeviceEntity*> taken_;
};

SimDevice device_at(const DeviceEntity& device, std::uint16_t port, int index) {
  if (index > 65535) throw WorldFileError(device.where, "more than 65536 devices of one interface on one port");
  return SimDevice{port, device.interface_code, static_cast<std::uint16_t>(index), device.model, device.driver_name};
}

std::vector<SimDevice> stage13_devices(const LoadContext& context) {
  IndexBook book;
  std::vector<SimDevice> devices(context.devices.size());
  const auto port_of = [&](const DeviceEntity& device) {
    return device.port != 0 ? device.port : context.options.default_port;
  };
  for (std::size_t i = 0; i < context.devices.size(); ++i) {
    const DeviceEntity& device = context.devices[i];
    if (!device.index) continue;
    const DeviceKey key{port_of(device), device.interface_code, *device.index};
    if (const DeviceEntity* other = book.holder(key)) {
      throw WorldFileError(device.where, protocol::interface_name(device.interface_code) + ":" +
                                             std::to_string(*device.index) + " on port " +
                                             std::to_string(port_of(device)) + " is given twice (also at " +
                                             to_string(other->where) + ")");
    }
    book.take(key, device);
    devices[i] = device_at(device, port_of(device), *device.index);
  }
  for (std::size_t i = 0; i < context.devices.size(); ++i) {
    const DeviceEntity& device = context.devices[i];
    if (device.index) continue;
    const std::uint16_t port = port_of(device);
    const int index = book.lowest_free(port, device.interface_code);
    book.take({port, device.interface_code, index}, device);
    devices[i] = device_at(device, port, index);
  }
  return devices;
}

std::vector<SimDevice> stage4_devices(const LoadContext& context) {
  IndexBook book;
  const std::uint16_t port = context.options.default_port;
  std::vector<SimDevice> devices;
  const auto place = [&](const DeviceEntity& device, int preferred) {
    int index = preferred;
    if (index < 0 || book.holder({port, device.interface_code, index}) != nullptr) {
      index = book.lowest_free(port, device.interface_code);
    }
    book.take({port, device.interface_code, index}, device);
    devices.push_back(device_at(device, port, index));
  };
  // Devices are listed robot by robot already (the walk is in world order).
  for (const DeviceEntity& device : context.devices) {
    if (device.robot >= 0) place(device, device.robot);
  }
  for (const DeviceEntity& device : context.devices) {
    if (device.robot < 0) place(device, -1);
  }
  return devices;
}

}  // namespace

std::vector<SimDevice> assign_device_indices(const LoadContext& context) {
  return context.dialect == Dialect::stage13 ? stage13_devices(context) : stage4_devices(context);
}

}  // namespace playerkit::sim::worldfile
