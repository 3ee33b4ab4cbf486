#pragma once
// `udpbroadcast` (manual §6.9, §7.43): lets clients of different servers talk.
// Every command written to the device (player_comms_cmd_t, any length) goes
// out as one UDP datagram to addr:port; every datagram arriving on the port,
// including the device's own, is published as the device's data.
//
// Options: addr (string, default "127.255.255.255" -- NOT 1.5's
// "10.255.255.255", on purpose: see lib/drivers/README.md) and port (int,
// default 6013). The socket is opened at the first subscription and closed at
// the last. Requests are answered NACK.

#include <cstdint>
#include <optional>
#include <stop_token>
#include <string_view>
#include <vector>

#include "core/driver.hpp"
#include "core/driver_registry.hpp"
#include "core/option_schema.hpp"
#include "drivers/comms/broadcast_socket.hpp"

namespace playerkit::drivers {

inline constexpr std::string_view kDefaultBroadcastAddress = "127.255.255.255";
inline constexpr int kDefaultBroadcastPort = 6013;

class UdpBroadcastDriver final : public core::ThreadedDriver {
 public:
  // Receives on destination.port and sends there.
  explicit UdpBroadcastDriver(Ipv4Endpoint destination);

  [[nodiscard]] const Ipv4Endpoint& destination() const { return destination_; }

 protected:
  void open() override;
  void close() override;
  void run(std::stop_token stop) override;

 private:
  void send_waiting_commands();
  void publish_waiting_datagrams();

  Ipv4Endpoint destination_;
  std::optional<BroadcastSocket> socket_;
  std::vector<std::uint8_t> receive_buffer_;
};

// addr (an IPv4 address) and port (1..65535), declared once.
const core::OptionSchema& udpbroadcast_option_schema();

// The destination of `addr` and `port`. Throws std::runtime_error naming the bad value.
Ipv4Endpoint read_broadcast_destination(std::string_view address, int port);

core::DriverSpec udpbroadcast_driver_spec();

}  // namespace playerkit::drivers
