#pragma once
// A real server on loopback, in a background thread, for end-to-end tests.
// The config text names ports as {PORT} (the -p port) and {PORT2}, {PORT3}
// (extra robot ports); all are chosen free at run time by binding port 0.

#include <chrono>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "core/device_table.hpp"
#include "core/driver_registry.hpp"
#include "server/server.hpp"
#include "support/eventually.hpp"

namespace playerkit::testing {

// Drivers the server tests use (registered by TestServer):
//   source      any interface, 'r'; publishes only what the test publishes
//   actuator    position, 'a'; keeps the commands it gets
//   echo        any interface, 'a'; ACKs subtype 1 with the request's bytes, NACKs others
//   refuser     any interface; setup() always fails
//   slowreply   any interface, 'a', own thread, request queue 1; answers after 200 ms
void register_test_drivers(core::DriverRegistry& registry);

class TestServer {
 public:
  explicit TestServer(const std::string& config_text, server::ServerOptions options = {},
                      int extra_ports = 0,
                      const std::function<void(core::DriverRegistry&)>& add_drivers = {});
  ~TestServer();
  TestServer(const TestServer&) = delete;
  TestServer& operator=(const TestServer&) = delete;

  [[nodiscard]] std::uint16_t port(std::size_t which = 0) const { return ports_.at(which); }
  core::Device& device(std::string_view address, std::size_t port_index = 0);
  core::DeviceTable& devices() { return devices_; }
  server::Server& server() { return *server_; }
  // Log lines so far, and whether one contains `text`.
  std::vector<std::string> log_lines() const;
  bool logged(std::string_view text) const;
  // Stops the server and shuts every device down; the destructor calls it too.
  void stop();

 private:
  core::ServerClock clock_;
  core::Logger logger_{"test-server"};
  mutable std::mutex log_mutex_;
  std::vector<std::string> log_;
  core::DriverRegistry registry_;
  core::DeviceTable devices_;
  std::unique_ptr<server::Server> server_;
  std::vector<std::uint16_t> ports_;
  std::thread thread_;
  bool stopped_ = false;
};

}  // namespace playerkit::testing
