#pragma once
// Plain POSIX UDP helpers for the udpbroadcast tests, independent of the code
// under test. Loopback only: everything goes to 127.0.0.1 or 127.255.255.255.

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace playerkit::drivers::testing {

inline constexpr const char* kLoopbackBroadcast = "127.255.255.255";

class UdpDescriptor {
 public:
  UdpDescriptor() : descriptor_(::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0)) {
    if (descriptor_ < 0) throw std::runtime_error("socket() failed");
  }
  UdpDescriptor(const UdpDescriptor&) = delete;
  UdpDescriptor& operator=(const UdpDescriptor&) = delete;
  ~UdpDescriptor() { ::close(descriptor_); }
  [[nodiscard]] int get() const { return descriptor_; }

  void enable(int option) const {
    const int on = 1;
    if (::setsockopt(descriptor_, SOL_SOCKET, option, &on, sizeof on) != 0) {
      throw std::runtime_error("setsockopt failed");
    }
  }
  [[nodiscard]] bool bind_to(const char* address, std::uint16_t port) const {
    sockaddr_in local{};
    local.sin_family = AF_INET;
    local.sin_port = htons(port);
    ::inet_pton(AF_INET, address, &local.sin_addr);
    return ::bind(descriptor_, reinterpret_cast<const sockaddr*>(&local), sizeof local) == 0;
  }

 private:
  int descriptor_;
};

// A port nobody uses right now: bind 127.0.0.1:0, read the port, close.
inline std::uint16_t free_udp_port() {
  const UdpDescriptor probe;
  if (!probe.bind_to("127.0.0.1", 0)) throw std::runtime_error("cannot bind a probe socket");
  sockaddr_in bound{};
  socklen_t length = sizeof bound;
  ::getsockname(probe.get(), reinterpret_cast<sockaddr*>(&bound), &length);
  return ntohs(bound.sin_port);
}

// True if a socket that does not share can take the port: nothing holds it.
inline bool port_is_free(std::uint16_t port) { return UdpDescriptor().bind_to("0.0.0.0", port); }

// Another program on the same port, listening and broadcasting the way a
// udpbroadcast device does.
class LoopbackPeer {
 public:
  explicit LoopbackPeer(std::uint16_t port) : port_(port) {
    socket_.enable(SO_REUSEADDR);
    socket_.enable(SO_REUSEPORT);
    socket_.enable(SO_BROADCAST);
    if (!socket_.bind_to("0.0.0.0", port)) throw std::runtime_error("peer cannot bind");
  }

  void broadcast(std::span<const std::uint8_t> bytes) const {
    sockaddr_in remote{};
    remote.sin_family = AF_INET;
    remote.sin_port = htons(port_);
    ::inet_pton(AF_INET, kLoopbackBroadcast, &remote.sin_addr);
    if (::sendto(socket_.get(), bytes.data(), bytes.size(), 0,
                 reinterpret_cast<const sockaddr*>(&remote), sizeof remote) < 0) {
      throw std::runtime_error("peer sendto failed");
    }
  }
  void broadcast(const std::string& text) const {
    broadcast(std::span(reinterpret_cast<const std::uint8_t*>(text.data()), text.size()));
  }

  // The next datagram, or nullopt if none arrives within `limit`.
  std::optional<std::string> receive(std::chrono::milliseconds limit) const {
    pollfd watched{socket_.get(), POLLIN, 0};
    if (::poll(&watched, 1, static_cast<int>(limit.count())) <= 0) return std::nullopt;
    std::vector<char> buffer(65536);
    const ssize_t length = ::recv(socket_.get(), buffer.data(), buffer.size(), MSG_DONTWAIT);
    if (length < 0) return std::nullopt;
    return std::string(buffer.data(), static_cast<std::size_t>(length));
  }

 private:
  UdpDescriptor socket_;
  std::uint16_t port_;
};

}  // namespace playerkit::drivers::testing
