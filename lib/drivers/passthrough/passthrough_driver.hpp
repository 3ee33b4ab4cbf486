#pragma once
// `passthrough` (manual §7.31): serves a device of another Player server as
// if it were local. One client connection per device to host:port, subscribed
// to the remote device of this device's interface and the configured index.
// Remote data is published here with the remote's timestamps; commands and
// requests written here are sent there, each reply going back to the client
// that asked.
//
// Options: host (string, default "localhost"), port (int, default 6665),
// index (int, default 0). The connection is made at the first subscription;
// a remote that cannot be reached, or that refuses the device, refuses the
// subscription ('e') with a log line naming host:port and the device. When
// the remote goes away later, the device is marked unavailable (newcomers get
// 'e', one log line) and the driver reconnects every second until it is back.

#include <chrono>
#include <cstdint>
#include <optional>
#include <stop_token>
#include <string>

#include "client/client.hpp"
#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "protocol/device_address.hpp"
#include "protocol/message.hpp"

namespace playerkit::drivers {

inline constexpr std::string_view kDefaultPassthroughHost = "localhost";
inline constexpr int kDefaultPassthroughPort = 6665;

struct RemoteDevice {
  std::string host;
  std::uint16_t port = 0;
  protocol::DeviceAddress address;  // on the remote server
};

// "laser:0 on localhost:6665", for log lines.
std::string to_string(const RemoteDevice& remote);

// Reads the options of one passthrough section for a device of `interface`.
// Throws std::runtime_error naming the bad option.
RemoteDevice read_remote_device(std::uint16_t interface, std::string_view host, int port,
                                int index);

struct PassthroughTimings {
  // Connecting, the banner and subscribing at setup, all within this. The
  // client opening the device waits for it; the server's other clients do not
  // (setup runs off the server's event loop: setup_may_block()).
  std::chrono::milliseconds connect_timeout{2000};
  // A forwarded request's reply; a remote that does not answer in time is
  // treated as lost (a late reply would be taken for the next one's).
  std::chrono::milliseconds request_timeout{5000};
  // Between reconnection attempts while the remote is away.
  std::chrono::milliseconds retry_interval{1000};
};

class PassthroughDriver final : public core::ThreadedDriver {
 public:
  explicit PassthroughDriver(RemoteDevice remote, PassthroughTimings timings = {});

  [[nodiscard]] const RemoteDevice& remote() const { return remote_; }
  // Connecting to the remote takes up to the connect timeout.
  [[nodiscard]] bool setup_may_block() const override { return true; }

 protected:
  void open() override;
  void close() override;
  void run(std::stop_token stop) override;
  core::RequestResult handle_request(const core::Request& request) override;

 private:
  // Connects, subscribes and selects the data mode. Throws DriverError.
  void connect_and_subscribe();
  void relay_one_round();
  void forward_commands();
  void lose_remote(const std::string& reason);
  void wait_for_remote(const std::stop_token& stop);

  RemoteDevice remote_;
  PassthroughTimings timings_;
  std::optional<client::Client> client_;  // empty while the remote is away
  protocol::Access granted_ = protocol::Access::kError;
  bool warned_read_only_ = false;
  std::chrono::steady_clock::time_point next_attempt_;
};

core::DriverSpec passthrough_driver_spec();

}  // namespace playerkit::drivers
