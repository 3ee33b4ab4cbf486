#include "links/tcp_link.hpp"

#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>

#include "links/link_address.hpp"
#include "links/link_error.hpp"

namespace playerkit::links {

namespace {

void set_socket_options(int fd) {
  const int on = 1;
  // Telegrams are small and latency matters more than packet count.
  (void)::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
  // A bridge that loses power never sends a FIN; keepalive eventually notices.
  (void)::setsockopt(fd, SOL_SOCKET, SO_KEEPALIVE, &on, sizeof on);
}

// One address: non-blocking connect, then poll for writability until the
// deadline. Returns the connected socket, or an invalid one and the errno.
UniqueFd try_connect(const addrinfo& address, Deadline deadline, int& error_number) {
  UniqueFd fd(::socket(address.ai_family, address.ai_socktype | SOCK_NONBLOCK | SOCK_CLOEXEC, address.ai_protocol));
  if (!fd.valid()) {
    error_number = errno;
    return {};
  }
  if (::connect(fd.get(), address.ai_addr, address.ai_addrlen) == 0) return fd;
  if (errno != EINPROGRESS) {
    error_number = errno;
    return {};
  }
  if (wait_for_fd(fd.get(), POLLOUT, deadline) == 0) {
    error_number = ETIMEDOUT;
    return {};
  }
  int socket_error = 0;
  socklen_t length = sizeof socket_error;
  if (::getsockopt(fd.get(), SOL_SOCKET, SO_ERROR, &socket_error, &length) != 0) socket_error = errno;
  if (socket_error != 0) {
    error_number = socket_error;
    return {};
  }
  return fd;
}

std::string connect_advice(int error_number) {
  switch (error_number) {
    case ECONNREFUSED: return "connection refused: is the bridge (ser2net) or emulator running and listening there?";
    case ETIMEDOUT: return "timed out: is the host up and the port not filtered by a firewall?";
    case EHOSTUNREACH:
    case ENETUNREACH: return std::string(std::strerror(error_number)) + ": check the address and the network";
    default: return std::strerror(error_number);
  }
}

}  // namespace

std::unique_ptr<TcpLink> TcpLink::connect(const std::string& host, std::uint16_t port, Deadline deadline) {
  std::unique_ptr<TcpLink> link(new TcpLink(host, port, to_string(LinkAddress::tcp(host, port))));
  link->dial(deadline);
  return link;
}

std::unique_ptr<TcpLink> TcpLink::adopt(UniqueFd socket, std::string description) {
  std::unique_ptr<TcpLink> link(new TcpLink("", 0, std::move(description)));
  // Every wait is a poll with a deadline; a blocking socket would defeat it.
  const int flags = ::fcntl(socket.get(), F_GETFL);
  if (flags < 0 || ::fcntl(socket.get(), F_SETFL, flags | O_NONBLOCK) != 0) {
    throw system_error(link->description_, "cannot make the socket non-blocking", errno);
  }
  set_socket_options(socket.get());
  link->fd_ = std::move(socket);
  return link;
}

TcpLink::TcpLink(std::string host, std::uint16_t port, std::string description)
    : host_(std::move(host)), port_(port), description_(std::move(description)) {}

TcpLink::~TcpLink() { close(); }

void TcpLink::dial(Deadline deadline) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_NUMERICSERV | AI_ADDRCONFIG;
  addrinfo* found = nullptr;
  const int resolved = ::getaddrinfo(host_.c_str(), std::to_string(port_).c_str(), &hints, &found);
  if (resolved != 0) {
    const std::string why = resolved == EAI_SYSTEM ? std::strerror(errno) : ::gai_strerror(resolved);
    throw LinkError(LinkErrorKind::connect_failed, description_,
                    description_ + ": cannot resolve host '" + host_ + "': " + why);
  }
  const std::unique_ptr<addrinfo, decltype(&::freeaddrinfo)> addresses(found, &::freeaddrinfo);
  int error_number = EHOSTUNREACH;
  for (const addrinfo* address = found; address != nullptr; address = address->ai_next) {
    UniqueFd fd = try_connect(*address, deadline, error_number);
    if (fd.valid()) {
      set_socket_options(fd.get());
      fd_ = std::move(fd);
      return;
    }
  }
  throw LinkError(LinkErrorKind::connect_failed, description_,
                  description_ + ": cannot connect: " + connect_advice(error_number));
}

int TcpLink::checked_fd() const {
  if (!fd_.valid()) throw LinkError(LinkErrorKind::closed, description_, description_ + " is closed");
  return fd_.get();
}

std::size_t TcpLink::read_available(std::span<std::uint8_t> buffer, Deadline deadline) {
  return read_with_deadline(checked_fd(), buffer, deadline, description_, "the peer closed the connection");
}

std::size_t TcpLink::write_available(std::span<const std::uint8_t> bytes, Deadline deadline) {
  return write_with_deadline(checked_fd(), bytes, deadline, description_, true);
}

void TcpLink::flush_input() {
  const int fd = checked_fd();
  std::array<std::uint8_t, 4096> discard{};
  while (true) {
    const ssize_t count = ::recv(fd, discard.data(), discard.size(), MSG_DONTWAIT);
    if (count > 0) {
      const auto bytes = std::span<const std::uint8_t>(discard).first(static_cast<std::size_t>(count));
      report(Direction::in, bytes);
      counters().bytes_dropped.add(bytes.size());
      continue;
    }
    if (count == 0) {
      throw LinkError(LinkErrorKind::disconnected, description_, description_ + ": the peer closed the connection");
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return;
    throw system_error(description_, "read failed", errno);
  }
}

void TcpLink::close() noexcept { fd_.reset(); }

void TcpLink::reopen(Deadline deadline) {
  if (port_ == 0) {
    throw LinkError(LinkErrorKind::closed, description_,
                    description_ + ": an accepted connection cannot be reopened; wait for the peer to connect again");
  }
  close();
  dial(deadline);
  counters().reconnects.add();
}

}  // namespace playerkit::links
