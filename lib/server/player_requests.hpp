#pragma once
// Answers to requests addressed to the `player` device itself (code 1): the
// device list, driver info, opening and closing devices, data mode, data
// frequency, data requests and the name service (server-behaviour.md §3).
// AUTH is handled by the session: while it is pending nothing reaches here.

#include <cstdint>
#include <span>
#include <vector>

#include "core/device_table.hpp"
#include "protocol/constants.hpp"
#include "server/client_state.hpp"

namespace playerkit::server {

struct PlayerReply {
  protocol::MessageType type = protocol::MessageType::kNack;
  std::vector<std::uint8_t> payload;
  bool round_requested = false;  // a pull-mode DATA request was accepted
  bool schedule_changed = false;  // mode or frequency changed: re-arm the push timer
};

PlayerReply answer_player_request(ClientState& client, std::span<const std::uint8_t> payload,
                                  const core::DeviceTable& devices);

}  // namespace playerkit::server
