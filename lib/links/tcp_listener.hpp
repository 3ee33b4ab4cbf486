#pragma once
// The serving side of a TCP link: an emulator waiting for a driver, or a
// test standing in for ser2net. Port 0 takes a free port chosen by the
// kernel (tests never hard-code one).

#include <cstdint>
#include <memory>
#include <string>

#include "links/deadline.hpp"
#include "links/fd_io.hpp"
#include "links/tcp_link.hpp"

namespace playerkit::links {

class TcpListener {
 public:
  // Binds and listens on host:port (host an address, "127.0.0.1" or "::1").
  // Throws LinkError(bad_address / io_error / busy when the port is taken).
  TcpListener(const std::string& host, std::uint16_t port);

  [[nodiscard]] std::uint16_t port() const { return port_; }
  // "tcp:127.0.0.1:40123": what a driver's `port` option should say.
  [[nodiscard]] std::string address() const;
  [[nodiscard]] int native_handle() const { return fd_.get(); }

  // The next connection, or nullptr when the deadline passes first.
  std::unique_ptr<TcpLink> accept(Deadline deadline);

 private:
  std::string host_;
  std::uint16_t port_ = 0;
  UniqueFd fd_;
};

}  // namespace playerkit::links
