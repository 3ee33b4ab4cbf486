#include "links/tcp_listener.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstring>

#include "links/link_address.hpp"
#include "links/link_error.hpp"

namespace playerkit::links {

TcpListener::TcpListener(const std::string& host, std::uint16_t port) : host_(host) {
  const std::string where = to_string(LinkAddress::tcp(host, port));
  sockaddr_storage storage{};
  socklen_t length = 0;
  auto* v4 = reinterpret_cast<sockaddr_in*>(&storage);
  auto* v6 = reinterpret_cast<sockaddr_in6*>(&storage);
  if (::inet_pton(AF_INET, host.c_str(), &v4->sin_addr) == 1) {
    v4->sin_family = AF_INET;
    v4->sin_port = htons(port);
    length = sizeof *v4;
  } else if (::inet_pton(AF_INET6, host.c_str(), &v6->sin6_addr) == 1) {
    v6->sin6_family = AF_INET6;
    v6->sin6_port = htons(port);
    length = sizeof *v6;
  } else {
    throw LinkError(LinkErrorKind::bad_address, where, where + ": listen on an IP address, not '" + host + "'");
  }
  fd_.reset(::socket(storage.ss_family, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  if (!fd_.valid()) throw system_error(where, "cannot create a socket", errno);
  const int on = 1;
  (void)::setsockopt(fd_.get(), SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  if (::bind(fd_.get(), reinterpret_cast<sockaddr*>(&storage), length) != 0) {
    const int error_number = errno;
    if (error_number == EADDRINUSE) {
      throw LinkError(LinkErrorKind::busy, where, where + ": the port is already in use");
    }
    throw system_error(where, "cannot bind", error_number);
  }
  if (::listen(fd_.get(), 4) != 0) throw system_error(where, "cannot listen", errno);
  socklen_t bound_length = sizeof storage;
  if (::getsockname(fd_.get(), reinterpret_cast<sockaddr*>(&storage), &bound_length) != 0) {
    throw system_error(where, "cannot read the bound port", errno);
  }
  port_ = ntohs(storage.ss_family == AF_INET ? v4->sin_port : v6->sin6_port);
}

std::string TcpListener::address() const { return to_string(LinkAddress::tcp(host_, port_)); }

std::unique_ptr<TcpLink> TcpListener::accept(Deadline deadline) {
  while (true) {
    sockaddr_storage peer{};
    socklen_t length = sizeof peer;
    UniqueFd connection(
        ::accept4(fd_.get(), reinterpret_cast<sockaddr*>(&peer), &length, SOCK_NONBLOCK | SOCK_CLOEXEC));
    if (connection.valid()) {
      char text[INET6_ADDRSTRLEN] = "?";
      std::uint16_t peer_port = 0;
      if (peer.ss_family == AF_INET) {
        const auto* v4 = reinterpret_cast<const sockaddr_in*>(&peer);
        ::inet_ntop(AF_INET, &v4->sin_addr, text, sizeof text);
        peer_port = ntohs(v4->sin_port);
      } else if (peer.ss_family == AF_INET6) {
        const auto* v6 = reinterpret_cast<const sockaddr_in6*>(&peer);
        ::inet_ntop(AF_INET6, &v6->sin6_addr, text, sizeof text);
        peer_port = ntohs(v6->sin6_port);
      }
      return TcpLink::adopt(std::move(connection), to_string(LinkAddress::tcp(text, peer_port)));
    }
    if (errno == EINTR || errno == ECONNABORTED) continue;
    if (errno != EAGAIN && errno != EWOULDBLOCK) throw system_error(address(), "accept failed", errno);
    if (wait_for_fd(fd_.get(), POLLIN, deadline) == 0) return nullptr;
  }
}

}  // namespace playerkit::links
