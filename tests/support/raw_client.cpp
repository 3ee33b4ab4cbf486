#include "support/raw_client.hpp"

#include <arpa/inet.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <utility>

namespace playerkit::testing {

namespace {

std::runtime_error system_error(const std::string& what) {
  return std::runtime_error(what + ": " + std::strerror(errno));
}

}  // namespace

std::vector<std::uint8_t> u16_bytes(std::uint16_t value) {
  return {static_cast<std::uint8_t>(value >> 8), static_cast<std::uint8_t>(value & 0xFF)};
}

RawClient::RawClient(std::uint16_t port, Options options) : options_(options) {
  fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
  if (fd_ < 0) throw system_error("socket");
  if (options_.receive_buffer_bytes > 0) {
    ::setsockopt(fd_, SOL_SOCKET, SO_RCVBUF, &options_.receive_buffer_bytes,
                 sizeof options_.receive_buffer_bytes);
  }
  sockaddr_in address{};
  address.sin_family = AF_INET;
  address.sin_port = htons(port);
  address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
  if (::connect(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) != 0) {
    const auto error = system_error("connect to 127.0.0.1:" + std::to_string(port));
    ::close(fd_);
    throw error;
  }
  const int one = 1;
  ::setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

RawClient::~RawClient() {
  if (fd_ >= 0) ::close(fd_);
}

RawClient::RawClient(RawClient&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)), options_(other.options_), pending_(std::move(other.pending_)) {}

bool RawClient::wait_readable(std::chrono::milliseconds timeout) {
  pollfd poll_fd{fd_, POLLIN, 0};
  const int ready = ::poll(&poll_fd, 1, static_cast<int>(timeout.count()));
  if (ready < 0) throw system_error("poll");
  return ready > 0;
}

std::vector<std::uint8_t> RawClient::read_exactly(std::size_t n) {
  const auto deadline = std::chrono::steady_clock::now() + options_.timeout;
  while (pending_.size() < n) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 || !wait_readable(left)) {
      throw std::runtime_error("timed out waiting for " + std::to_string(n) + " bytes (have " +
                               std::to_string(pending_.size()) + ")");
    }
    std::uint8_t chunk[65536];
    const ssize_t got = ::recv(fd_, chunk, sizeof chunk, 0);
    if (got == 0) throw std::runtime_error("the server closed the connection");
    if (got < 0) throw system_error("recv");
    pending_.insert(pending_.end(), chunk, chunk + got);
  }
  std::vector<std::uint8_t> bytes(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
  pending_.erase(pending_.begin(), pending_.begin() + static_cast<std::ptrdiff_t>(n));
  return bytes;
}

std::optional<protocol::Message> RawClient::read_message(std::chrono::milliseconds timeout) {
  const auto saved = options_.timeout;
  options_.timeout = timeout;
  std::optional<protocol::Message> message;
  try {
    const auto header_bytes = read_exactly(protocol::kHeaderSize);
    std::array<std::uint8_t, protocol::kHeaderSize> header_array{};
    std::copy(header_bytes.begin(), header_bytes.end(), header_array.begin());
    protocol::Message m;
    m.header = protocol::decode_header(header_array);
    if (m.header.stx != protocol::kStx) throw std::runtime_error("bad stx from the server");
    m.payload = read_exactly(m.header.size);
    message = std::move(m);
  } catch (const std::runtime_error& e) {
    options_.timeout = saved;
    if (std::string(e.what()).starts_with("timed out")) return std::nullopt;
    throw;
  }
  options_.timeout = saved;
  return message;
}

bool RawClient::wait_for_close(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left = std::chrono::duration_cast<std::chrono::milliseconds>(
        deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0 || !wait_readable(left)) return false;
    std::uint8_t chunk[65536];
    const ssize_t got = ::recv(fd_, chunk, sizeof chunk, 0);
    if (got == 0) return true;
    if (got < 0) return errno == ECONNRESET;
  }
}

void RawClient::send_bytes(std::span<const std::uint8_t> bytes) {
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::send(fd_, bytes.data() + sent, bytes.size() - sent, MSG_NOSIGNAL);
    if (n < 0) throw system_error("send");
    sent += static_cast<std::size_t>(n);
  }
}

void RawClient::send(protocol::MessageType type, protocol::DeviceAddress device,
                     std::span<const std::uint8_t> payload) {
  send_bytes(protocol::encode_message(protocol::make_header(type, device, {}, {}), payload));
}

protocol::Message RawClient::request(protocol::DeviceAddress device,
                                     std::span<const std::uint8_t> payload) {
  send_request(device, payload);
  for (int skipped = 0; skipped < 1000; ++skipped) {
    protocol::Message message = read_message();
    if (protocol::is_reply(message.type())) return message;
  }
  throw std::runtime_error("no reply within 1000 messages");
}

char RawClient::open(protocol::DeviceAddress device, char access) {
  std::vector<std::uint8_t> payload = u16_bytes(protocol::kPlayerDevReq);
  for (auto part : {u16_bytes(device.interface), u16_bytes(device.index)}) {
    payload.insert(payload.end(), part.begin(), part.end());
  }
  payload.push_back(static_cast<std::uint8_t>(access));
  const auto reply = player_request(payload);
  if (reply.type() != protocol::MessageType::kAck || reply.payload.size() != 71) {
    throw std::runtime_error("DEV request was not acknowledged with 71 bytes");
  }
  return static_cast<char>(reply.payload[6]);
}

protocol::MessageType RawClient::set_data_mode(protocol::DataMode mode) {
  auto payload = u16_bytes(protocol::kPlayerDatamodeReq);
  payload.push_back(static_cast<std::uint8_t>(mode));
  return player_request(payload).type();
}

protocol::MessageType RawClient::set_frequency(std::uint16_t hz) {
  auto payload = u16_bytes(protocol::kPlayerDatafreqReq);
  const auto value = u16_bytes(hz);
  payload.insert(payload.end(), value.begin(), value.end());
  return player_request(payload).type();
}

std::vector<protocol::Message> RawClient::read_round() {
  std::vector<protocol::Message> round;
  for (;;) {
    round.push_back(read_message());
    if (round.back().type() == protocol::MessageType::kSynch) return round;
  }
}

}  // namespace playerkit::testing
