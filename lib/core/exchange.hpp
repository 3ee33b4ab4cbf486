#pragma once
// What flows through a device besides its data: commands in, configuration
// requests in, replies out. Payloads are wire bytes (lib/protocol encodes them).

#include <cstdint>
#include <vector>

#include "protocol/constants.hpp"
#include "protocol/device_address.hpp"
#include "protocol/message.hpp"

namespace playerkit::core {

using protocol::DeviceAddress;
using protocol::Timestamp;

// Who sent a request, so that its reply finds the way back. The server numbers
// its connections from 1; drivers that talk to other devices use their own ids.
using ClientId = std::uint64_t;
inline constexpr ClientId kNoClient = 0;
// Drivers asking the devices they are built on number themselves from here
// (core/source_request.hpp), far above any count of server connections.
inline constexpr ClientId kFirstDriverClient = ClientId{1} << 62;

// The latest data a device published. sequence counts publications from 1; 0
// means the device has never published.
struct DataSample {
  std::vector<std::uint8_t> payload;
  Timestamp timestamp;
  std::uint64_t sequence = 0;
};

struct Command {
  std::vector<std::uint8_t> payload;
  Timestamp received;
  ClientId client = kNoClient;
};

struct Request {
  ClientId client = kNoClient;
  DeviceAddress device;  // as addressed in the request header
  std::vector<std::uint8_t> payload;
  Timestamp received;

  // The first payload byte: every interface but `player` uses a uint8 subtype.
  [[nodiscard]] std::uint8_t subtype() const { return payload.empty() ? 0 : payload.front(); }
};

// A driver's answer to one request: ACK with a payload, or NACK.
struct RequestResult {
  protocol::MessageType type = protocol::MessageType::kNack;
  std::vector<std::uint8_t> payload;

  static RequestResult ack(std::vector<std::uint8_t> payload = {}) {
    return {protocol::MessageType::kAck, std::move(payload)};
  }
  static RequestResult nack() { return {protocol::MessageType::kNack, {}}; }
};

struct Reply {
  ClientId client = kNoClient;
  DeviceAddress device;  // copied from the request: clients check it
  protocol::MessageType type = protocol::MessageType::kNack;
  std::vector<std::uint8_t> payload;
  Timestamp timestamp;  // when the driver answered
};

}  // namespace playerkit::core
