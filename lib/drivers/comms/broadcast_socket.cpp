#include "drivers/comms/broadcast_socket.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <system_error>
#include <utility>

namespace playerkit::drivers {

namespace {

[[noreturn]] void throw_errno(const std::string& what) {
  throw std::system_error(errno, std::generic_category(), what);
}

void enable_option(int descriptor, int option, const char* name) {
  const int on = 1;
  if (::setsockopt(descriptor, SOL_SOCKET, option, &on, sizeof on) != 0) {
    throw_errno(std::string("setsockopt(") + name + ")");
  }
}

}  // namespace

std::optional<Ipv4Endpoint> Ipv4Endpoint::parse(std::string_view address, std::uint16_t port) {
  in_addr parsed{};
  const std::string text(address);  // inet_pton wants a terminated string
  if (::inet_pton(AF_INET, text.c_str(), &parsed) != 1) return std::nullopt;
  return Ipv4Endpoint{ntohl(parsed.s_addr), port};
}

std::string Ipv4Endpoint::to_string() const {
  return std::to_string((address >> 24) & 0xFF) + "." + std::to_string((address >> 16) & 0xFF) +
         "." + std::to_string((address >> 8) & 0xFF) + "." + std::to_string(address & 0xFF) + ":" +
         std::to_string(port);
}

BroadcastSocket BroadcastSocket::bind_shared(std::uint16_t port) {
  const int descriptor = ::socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
  if (descriptor < 0) throw_errno("socket");
  BroadcastSocket socket(descriptor);  // closes the descriptor if a step below throws

  enable_option(descriptor, SO_REUSEADDR, "SO_REUSEADDR");
  enable_option(descriptor, SO_REUSEPORT, "SO_REUSEPORT");
  enable_option(descriptor, SO_BROADCAST, "SO_BROADCAST");

  sockaddr_in local{};
  local.sin_family = AF_INET;
  local.sin_addr.s_addr = htonl(INADDR_ANY);
  local.sin_port = htons(port);
  if (::bind(descriptor, reinterpret_cast<const sockaddr*>(&local), sizeof local) != 0) {
    throw_errno("bind to port " + std::to_string(port));
  }
  return socket;
}

BroadcastSocket::BroadcastSocket(BroadcastSocket&& other) noexcept
    : descriptor_(std::exchange(other.descriptor_, -1)) {}

BroadcastSocket& BroadcastSocket::operator=(BroadcastSocket&& other) noexcept {
  if (this != &other) {
    close();
    descriptor_ = std::exchange(other.descriptor_, -1);
  }
  return *this;
}

BroadcastSocket::~BroadcastSocket() { close(); }

void BroadcastSocket::close() noexcept {
  if (descriptor_ >= 0) ::close(descriptor_);
  descriptor_ = -1;
}

void BroadcastSocket::send_to(const Ipv4Endpoint& destination,
                              std::span<const std::uint8_t> bytes) const {
  sockaddr_in remote{};
  remote.sin_family = AF_INET;
  remote.sin_addr.s_addr = htonl(destination.address);
  remote.sin_port = htons(destination.port);
  const ssize_t sent = ::sendto(descriptor_, bytes.data(), bytes.size(), MSG_NOSIGNAL,
                                reinterpret_cast<const sockaddr*>(&remote), sizeof remote);
  if (sent < 0) throw_errno("sendto " + destination.to_string());
}

bool BroadcastSocket::wait_readable(std::chrono::milliseconds timeout) const {
  pollfd watched{descriptor_, POLLIN, 0};
  const int ready = ::poll(&watched, 1, static_cast<int>(timeout.count()));
  // EINTR is just an early wake-up; the caller's loop polls again.
  return ready > 0 && (watched.revents & (POLLIN | POLLERR)) != 0;
}

std::optional<std::size_t> BroadcastSocket::receive(std::span<std::uint8_t> buffer) const {
  for (;;) {
    // MSG_TRUNC makes Linux report the datagram's real length even when the
    // buffer was too small, so oversized messages can be told apart.
    const ssize_t length = ::recv(descriptor_, buffer.data(), buffer.size(), MSG_DONTWAIT | MSG_TRUNC);
    if (length >= 0) return static_cast<std::size_t>(length);
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return std::nullopt;
    throw_errno("recv");
  }
}

}  // namespace playerkit::drivers
