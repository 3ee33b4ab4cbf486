// The appendix A functions on client::Client. Every entry point is noexcept:
// an exception (bad argument, refused or lost connection, timeout) becomes -1
// and one line on stderr, as 1.5's diagnostics did, subject to the debug level.

#include "client/c/playercclient.h"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstring>
#include <exception>
#include <memory>
#include <stdexcept>
#include <string>

#include "client/client.hpp"
#include "protocol/banner.hpp"
#include "protocol/messages/header.hpp"
#include "protocol/messages/player.hpp"
#include "protocol/messages/position.hpp"

// The C struct layouts are the wire's, byte for byte.
static_assert(sizeof(player_msghdr_t) == playerkit::protocol::MessageHeader::kWireSize);
static_assert(sizeof(player_device_req_t) == playerkit::protocol::DeviceAccessRequest::kWireSize);
static_assert(sizeof(player_device_resp_t) == playerkit::protocol::DeviceAccessReply::kWireSize);
static_assert(sizeof(player_position_cmd_t) == playerkit::protocol::PositionCommand::kWireSize);
static_assert(PLAYER_MAX_MESSAGE_SIZE == playerkit::protocol::kMaxMessageSize);
static_assert(PLAYER_MAX_PAYLOAD_SIZE == playerkit::protocol::kMaxPayloadSize);
static_assert(PLAYER_IDENT_STRLEN == playerkit::protocol::kBannerSize);
static_assert(PLAYER_PORTNUM == playerkit::protocol::kDefaultPort);
static_assert(PLAYER_STXX == playerkit::protocol::kStx);

struct player_connection_impl {
  playerkit::client::Client client;
};

namespace {

namespace client = playerkit::client;
namespace protocol = playerkit::protocol;
using namespace std::chrono_literals;

// 1.5 waited without limit for a connection, a message or a reply. These are
// long enough for any server that is alive and bound the wait for one that
// is not. A read may wait for data a pull-mode program has not asked for yet.
constexpr auto kConnectTimeout = 10s;
constexpr auto kReplyTimeout = 30s;
constexpr std::chrono::milliseconds kReadWait = 24h;

constexpr int kErrorLevel = 1;    // a call returns -1
constexpr int kWarningLevel = 2;  // a call succeeds, but not quite as asked

std::atomic<int> debug_level{PLAYER_CCLIENT_DEBUG_LEVEL_DEFAULT};

// No allocation: this runs inside catch blocks of noexcept functions.
void print_diagnostic(int level, const char* function, const char* what) noexcept {
  if (debug_level.load() >= level) std::fprintf(stderr, "%s(): %s\n", function, what);
}

// Runs `body`, turning any exception into -1 and a diagnostic.
template <typename Body>
int guarded(const char* function, Body&& body) noexcept {
  try {
    return body();
  } catch (const std::exception& error) {
    print_diagnostic(kErrorLevel, function, error.what());
  } catch (...) {
    print_diagnostic(kErrorLevel, function, "unexpected error");
  }
  return -1;
}

void require(bool condition, const char* what_is_wrong) {
  if (!condition) throw std::invalid_argument(what_is_wrong);
}

client::Client& connected(player_connection_t* conn) {
  require(conn != nullptr, "conn is NULL");
  require(conn->impl != nullptr, "not connected (player_connect failed or player_disconnect was called)");
  return conn->impl->client;
}

void require_payload(const char* bytes, std::size_t length, const char* name) {
  if (bytes == nullptr && length > 0) {
    throw std::invalid_argument(std::string(name) + " is NULL but its length is " + std::to_string(length));
  }
  if (length > PLAYER_MAX_PAYLOAD_SIZE) {
    throw std::invalid_argument(std::string(name) + " of " + std::to_string(length) +
                                " bytes is longer than PLAYER_MAX_PAYLOAD_SIZE (" +
                                std::to_string(PLAYER_MAX_PAYLOAD_SIZE) + "); nothing sent");
  }
}

std::span<const std::uint8_t> as_bytes(const char* bytes, std::size_t length) {
  return {reinterpret_cast<const std::uint8_t*>(bytes), length};
}

player_msghdr_t to_host_order_header(const protocol::Message& message) {
  player_msghdr_t header{};
  header.stx = message.header.stx;
  header.type = message.header.type;
  header.device = message.header.device;
  header.device_index = message.header.device_index;
  header.time_sec = message.header.time_sec;
  header.time_usec = message.header.time_usec;
  header.timestamp_sec = message.header.timestamp_sec;
  header.timestamp_usec = message.header.timestamp_usec;
  header.reserved = message.header.reserved;
  header.size = static_cast<std::uint32_t>(message.payload.size());
  return header;
}

// Copies what fits; the caller's header still tells the full size.
void copy_payload(const protocol::Message& message, char* destination, std::size_t capacity,
                  const char* function) {
  const std::size_t length = std::min(message.payload.size(), capacity);
  if (length > 0) std::memcpy(destination, message.payload.data(), length);
  if (message.payload.size() > capacity && debug_level.load() >= kWarningLevel) {
    const std::string what = "payload of " + std::to_string(message.payload.size()) +
                             " bytes cut to the buffer's " + std::to_string(capacity);
    print_diagnostic(kWarningLevel, function, what.c_str());
  }
}

}  // namespace

extern "C" {

int player_debug_level(int level) {
  if (level < 0) return debug_level.load();
  return debug_level.exchange(level);
}

int player_connect(player_connection_t* conn, const char* host, int port) {
  return guarded("player_connect", [&] {
    require(conn != nullptr, "conn is NULL");
    // Whatever conn held is not ours to free: 1.5 programs pass uninitialised structs.
    conn->sock = -1;
    conn->impl = nullptr;
    std::memset(conn->banner, 0, sizeof conn->banner);
    require(host != nullptr, "host is NULL");
    if (port < 1 || port > 65535) {
      throw std::invalid_argument("port " + std::to_string(port) + " is not in 1-65535");
    }
    auto impl = std::unique_ptr<player_connection_impl>(new player_connection_impl{
        client::Client::connect(host, static_cast<std::uint16_t>(port), kConnectTimeout)});
    impl->client.set_timeout(kReplyTimeout);
    const auto banner = protocol::make_banner(impl->client.server_version());
    std::memcpy(conn->banner, banner.data(), sizeof conn->banner);
    conn->sock = impl->client.native_handle();
    conn->impl = impl.release();
    return 0;
  });
}

int player_disconnect(player_connection_t* conn) {
  return guarded("player_disconnect", [&] {
    connected(conn);
    delete conn->impl;  // the Client closes its socket
    conn->impl = nullptr;
    conn->sock = -1;
    return 0;
  });
}

int player_request_device_access(player_connection_t* conn, uint16_t device,
                                 uint16_t device_index, uint8_t req_access,
                                 uint8_t* grant_access) {
  return guarded("player_request_device_access", [&] {
    const auto grant = connected(conn).request_access({device, device_index},
                                                      static_cast<protocol::Access>(req_access));
    const auto granted = static_cast<uint8_t>(grant.access);
    if (grant_access != nullptr) {
      *grant_access = granted;
    } else if (granted != req_access && debug_level.load() >= kWarningLevel) {
      const std::string what = std::string("asked for '") + static_cast<char>(req_access) +
                               "' access to " + protocol::to_string(protocol::DeviceAddress{device, device_index}) +
                               ", got '" + static_cast<char>(granted) + "'";
      print_diagnostic(kWarningLevel, "player_request_device_access", what.c_str());
    }
    return 0;
  });
}

int player_read(player_connection_t* conn, player_msghdr_t* hdr, char* payload, size_t payloadlen) {
  return guarded("player_read", [&] {
    client::Client& client = connected(conn);
    require(hdr != nullptr, "hdr is NULL");
    require(payload != nullptr || payloadlen == 0, "payload is NULL but payloadlen is not 0");
    auto message = client.read(kReadWait);
    if (!message) throw client::TimeoutError("no message from the server in 24 hours");
    *hdr = to_host_order_header(*message);
    copy_payload(*message, payload, payloadlen, "player_read");
    return 0;
  });
}

int player_write(player_connection_t* conn, uint16_t device, uint16_t device_index,
                 const char* command, size_t commandlen) {
  return guarded("player_write", [&] {
    client::Client& client = connected(conn);
    require_payload(command, commandlen, "command");
    client.write_command({device, device_index}, as_bytes(command, commandlen));
    return 0;
  });
}

int player_request(player_connection_t* conn, uint16_t device, uint16_t device_index,
                   const char* payload, size_t payloadlen, player_msghdr_t* replyhdr, char* reply,
                   size_t replylen) {
  return guarded("player_request", [&] {
    client::Client& client = connected(conn);
    require_payload(payload, payloadlen, "payload");
    // A 1.5 server drops zero-length messages without a reply: waiting would hang.
    require(payloadlen > 0, "a request needs a payload (at least its subtype)");
    const auto answer = client.request({device, device_index}, as_bytes(payload, payloadlen));
    if (replyhdr != nullptr) *replyhdr = to_host_order_header(answer);
    if (reply != nullptr) copy_payload(answer, reply, replylen, "player_request");
    return 0;
  });
}

}  // extern "C"
