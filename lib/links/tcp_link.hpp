#pragma once
// A TCP connection as a ByteLink: serial-over-network bridges (ser2net, a
// Moxa box) and emulators listening on a port. TCP_NODELAY, so a 6-byte
// command leaves at once instead of waiting for more.
//
// A peer that closes or resets reads (and writes) as LinkError(disconnected);
// the driver logs it, stops publishing, and calls reopen() to reconnect.

#include <cstdint>
#include <memory>
#include <string>

#include "links/byte_link.hpp"
#include "links/fd_io.hpp"

namespace playerkit::links {

class TcpLink final : public ByteLink {
 public:
  // Resolves `host` and connects to the first address that answers before
  // the deadline. Throws LinkError(connect_failed) saying why (unknown host,
  // refused, timed out). Name resolution itself is not bounded by the
  // deadline (getaddrinfo cannot be); addresses are.
  static std::unique_ptr<TcpLink> connect(const std::string& host, std::uint16_t port, Deadline deadline);

  // Takes over a connected socket (an accepted connection); reopen() on it
  // throws, since there is nothing to dial.
  static std::unique_ptr<TcpLink> adopt(UniqueFd socket, std::string description);

  ~TcpLink() override;

  // Reads and drops whatever has arrived (counted as dropped, traced).
  void flush_input() override;
  // Returns at once: the kernel sends on its own.
  void drain() override {}
  void close() noexcept override;
  [[nodiscard]] bool is_open() const override { return fd_.valid(); }
  void reopen(Deadline deadline) override;

  // "tcp:127.0.0.1:4001", "tcp:[::1]:4001"
  [[nodiscard]] std::string describe() const override { return description_; }
  [[nodiscard]] int native_handle() const override { return fd_.get(); }

 protected:
  std::size_t read_available(std::span<std::uint8_t> buffer, Deadline deadline) override;
  std::size_t write_available(std::span<const std::uint8_t> bytes, Deadline deadline) override;

 private:
  TcpLink(std::string host, std::uint16_t port, std::string description);
  void dial(Deadline deadline);
  int checked_fd() const;

  std::string host_;
  std::uint16_t port_ = 0;  // 0: adopted, cannot redial
  std::string description_;
  UniqueFd fd_;
};

}  // namespace playerkit::links
