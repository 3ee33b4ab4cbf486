#pragma once
// Checked access to the wire struct a message carries:
//
//   auto scan = client::data_as<protocol::LaserData>(message);   // throws if not laser data
//   auto geom = client::reply_as<protocol::LaserGeom>(reply);     // throws on NACK/ERR
//
// The struct names its interface through the catalog (its C name is the data,
// command or reply struct of that interface), so a position message read as
// LaserData, or a NACK read as a reply, is refused with MessageKindError
// before a byte is decoded. Payloads that do not fit the struct throw
// protocol::DecodeError (a zero-length data packet, which readlog sends before
// its first log line, is one: check payload.empty() first when replaying).

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string_view>

#include "protocol/binary_codec.hpp"
#include "protocol/fields.hpp"
#include "protocol/message.hpp"

namespace playerkit::client {

// A message of another type or interface than the struct it was read as.
class MessageKindError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace detail {
void check_data(const protocol::Message& message, std::string_view wire_name);
void check_command(const protocol::Message& message, std::string_view wire_name);
void check_reply(const protocol::Message& message, std::string_view wire_name,
                 std::optional<std::uint16_t> request_subtype);
}  // namespace detail

template <protocol::WireStruct T>
T data_as(const protocol::Message& message) {
  detail::check_data(message, T::kWireName);
  return protocol::decode<T>(message.payload);
}

template <protocol::WireStruct T>
T command_as(const protocol::Message& message) {
  detail::check_command(message, T::kWireName);
  return protocol::decode<T>(message.payload);
}

// An ACK's payload. request_subtype, when given, must be a request of the
// message's interface that is answered with T.
template <protocol::WireStruct T>
T reply_as(const protocol::Message& message, std::optional<std::uint16_t> request_subtype = std::nullopt) {
  detail::check_reply(message, T::kWireName, request_subtype);
  return protocol::decode<T>(message.payload);
}

}  // namespace playerkit::client
