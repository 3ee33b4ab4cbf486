#pragma once
// A UDP socket for the udpbroadcast driver: bound to every local address on
// one port, shared with every other socket on the machine that binds the same
// port the same way (so several devices and servers can listen together), and
// allowed to send to broadcast addresses. POSIX only.

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace playerkit::drivers {

struct Ipv4Endpoint {
  std::uint32_t address = 0;  // host byte order
  std::uint16_t port = 0;

  // Dotted quad only ("127.255.255.255"), like 1.5's inet_addr; no host names.
  static std::optional<Ipv4Endpoint> parse(std::string_view address, std::uint16_t port);
  // "127.255.255.255:6013"
  [[nodiscard]] std::string to_string() const;

  friend bool operator==(const Ipv4Endpoint&, const Ipv4Endpoint&) = default;
};

class BroadcastSocket {
 public:
  // Binds 0.0.0.0:port with SO_REUSEADDR, SO_REUSEPORT and SO_BROADCAST.
  // Throws std::system_error when any step fails (e.g. the port is held by a
  // socket that did not ask to share it).
  static BroadcastSocket bind_shared(std::uint16_t port);

  BroadcastSocket(BroadcastSocket&& other) noexcept;
  BroadcastSocket& operator=(BroadcastSocket&& other) noexcept;
  BroadcastSocket(const BroadcastSocket&) = delete;
  BroadcastSocket& operator=(const BroadcastSocket&) = delete;
  ~BroadcastSocket();

  // One datagram. Throws std::system_error.
  void send_to(const Ipv4Endpoint& destination, std::span<const std::uint8_t> bytes) const;
  // True as soon as a datagram is waiting; false when `timeout` passes first.
  [[nodiscard]] bool wait_readable(std::chrono::milliseconds timeout) const;
  // Copies the next waiting datagram into `buffer` without blocking and
  // returns its full length, which exceeds buffer.size() when it was cut
  // short; nullopt when nothing is waiting. Throws std::system_error.
  std::optional<std::size_t> receive(std::span<std::uint8_t> buffer) const;

 private:
  explicit BroadcastSocket(int descriptor) : descriptor_(descriptor) {}
  void close() noexcept;

  int descriptor_ = -1;
};

}  // namespace playerkit::drivers
