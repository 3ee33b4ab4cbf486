#pragma once
// Every device the server serves, keyed by (port, interface, index), in the
// order the config file declared them (DEVLIST reports that order).

#include <cstdint>
#include <memory>
#include <string_view>
#include <vector>

#include "core/device.hpp"
#include "core/shared_connection.hpp"

namespace playerkit::core {

class DeviceTable {
 public:
  DeviceTable() = default;
  // shutdown_all(), then the devices are destroyed last declared first: a
  // driver built on other devices (amcl on a laser) lets go of them in its
  // shutdown and destructor, and they must still be there then.
  ~DeviceTable();
  DeviceTable(const DeviceTable&) = delete;
  DeviceTable& operator=(const DeviceTable&) = delete;

  // A device with the same key replaces the old one in its place.
  Device& add(std::unique_ptr<Device> device);

  [[nodiscard]] Device* find(const DeviceKey& key) const;
  [[nodiscard]] Device* find(std::uint16_t port, DeviceAddress address) const {
    return find(DeviceKey{port, address});
  }
  [[nodiscard]] std::vector<Device*> on_port(std::uint16_t port) const;
  // The first device (any port) whose robot name matches exactly.
  [[nodiscard]] const Device* find_robot(std::string_view robot_name) const;
  // Distinct ports in order of first use.
  [[nodiscard]] std::vector<std::uint16_t> ports() const;
  [[nodiscard]] std::vector<Device*> all() const;
  [[nodiscard]] bool empty() const { return devices_.empty(); }
  [[nodiscard]] std::size_t size() const { return devices_.size(); }

  // prepare() on every device, once before serving.
  void prepare_all();
  // Subscribes every alwayson device once, for good. Throws std::runtime_error
  // naming the first device whose setup fails.
  void start_alwayson();
  // Shuts down every device still subscribed, last declared first (drivers
  // built on other devices go before the devices they use).
  void shutdown_all();

  // The hardware connections the drivers of these devices share.
  [[nodiscard]] ConnectionPool& connections() { return connections_; }

 private:
  // Before devices_, so that it outlives every driver holding a connection.
  ConnectionPool connections_;
  std::vector<std::unique_ptr<Device>> devices_;
};

}  // namespace playerkit::core
