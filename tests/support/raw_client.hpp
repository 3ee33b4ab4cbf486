#pragma once
// A deliberately plain Player client for tests: blocking POSIX sockets, every
// wait bounded by a timeout, every byte visible. It checks the server without
// sharing code with it (only lib/protocol's encoders).

#include <chrono>
#include <cstdint>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "protocol/constants.hpp"
#include "protocol/device_address.hpp"
#include "protocol/message.hpp"

namespace playerkit::testing {

using namespace std::chrono_literals;

class RawClient {
 public:
  struct Options {
    // Set before connecting; a small receive buffer makes a stalled client
    // fill up quickly.
    int receive_buffer_bytes = 0;
    std::chrono::milliseconds timeout = 5s;
  };

  // Connects to 127.0.0.1:port. Throws std::runtime_error on failure.
  explicit RawClient(std::uint16_t port) : RawClient(port, Options{}) {}
  RawClient(std::uint16_t port, Options options);
  ~RawClient();
  RawClient(RawClient&& other) noexcept;
  RawClient& operator=(RawClient&&) = delete;
  RawClient(const RawClient&) = delete;

  // Exactly n bytes, or throws (timeout, or the server closed).
  std::vector<std::uint8_t> read_exactly(std::size_t n);
  // The 32 banner bytes.
  std::vector<std::uint8_t> read_banner() { return read_exactly(protocol::kBannerSize); }
  // The next whole message; nullopt if none arrives within `timeout`.
  std::optional<protocol::Message> read_message(std::chrono::milliseconds timeout);
  protocol::Message read_message() {
    auto message = read_message(options_.timeout);
    if (!message) throw std::runtime_error("no message within the timeout");
    return *message;
  }
  // True when the server closes the connection within `timeout` (bytes that
  // arrive first are discarded).
  bool wait_for_close(std::chrono::milliseconds timeout);

  void send_bytes(std::span<const std::uint8_t> bytes);
  void send(protocol::MessageType type, protocol::DeviceAddress device,
            std::span<const std::uint8_t> payload);
  void send_request(protocol::DeviceAddress device, std::span<const std::uint8_t> payload) {
    send(protocol::MessageType::kRequest, device, payload);
  }

  // Sends a request and returns its reply, skipping data and SYNCH messages on
  // the way (as the 1.5 client library does).
  protocol::Message request(protocol::DeviceAddress device, std::span<const std::uint8_t> payload);
  protocol::Message player_request(std::vector<std::uint8_t> payload) {
    return request({1, 0}, payload);
  }
  // DEV request; returns the access letter granted.
  char open(protocol::DeviceAddress device, char access);
  // DATAMODE / DATAFREQ requests; return the reply type.
  protocol::MessageType set_data_mode(protocol::DataMode mode);
  protocol::MessageType set_frequency(std::uint16_t hz);

  // Messages until (and including) the next SYNCH.
  std::vector<protocol::Message> read_round();

  [[nodiscard]] int fd() const { return fd_; }

 private:
  // Waits for readability; false on timeout.
  bool wait_readable(std::chrono::milliseconds timeout);

  int fd_ = -1;
  Options options_;
  std::vector<std::uint8_t> pending_;
};

// Big-endian helpers for hand-written payloads.
std::vector<std::uint8_t> u16_bytes(std::uint16_t value);

}  // namespace playerkit::testing
