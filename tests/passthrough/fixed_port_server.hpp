#pragma once
// A robot's server on a port the test chooses, so that it can stop and come
// back on the port it left (TestServer always takes a fresh one). It serves
// the test drivers of tests/server/test_server.hpp (source, actuator, ...).

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <thread>

#include "core/server_clock.hpp"
#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "core/logger.hpp"
#include "server/server.hpp"

namespace playerkit::testing {

class FixedPortServer {
 public:
  // Port 0 picks a free one; `{PORT}` in the config text becomes the port.
  FixedPortServer(const std::string& config_text, std::uint16_t port);
  ~FixedPortServer();
  FixedPortServer(const FixedPortServer&) = delete;
  FixedPortServer& operator=(const FixedPortServer&) = delete;

  [[nodiscard]] std::uint16_t port() const { return port_; }
  core::Device& device(std::string_view address);

 private:
  core::ServerClock clock_;
  core::Logger logger_{"robot"};
  core::DriverRegistry registry_;
  core::DeviceTable devices_;
  std::unique_ptr<server::Server> server_;
  std::uint16_t port_ = 0;
  std::thread thread_;
};

}  // namespace playerkit::testing
