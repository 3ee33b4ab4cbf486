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

// The first device whose setup() must run off the event loop before
// `device` can be set up on it: `device` itself when its driver's setup may
// block (core::Driver::setup_may_block()), else the first such device among
// its sources (core::Driver::source_devices(), and theirs) that is not
// running yet; nullptr when there is none.
core::Device* blocking_setup_among(core::Device& device, const core::DeviceTable& devices);

// A request (to the `player` device) that must wait for a device's setup()
// off the event loop before it can be answered: a DEV request that would be
// the device's first subscription, when blocking_setup_among() finds a device
// to set up first. That device (the one asked for, or one of its sources), or
// nullptr for requests answered at once.
struct SetupFirst {
  core::Device* device = nullptr;
  bool is_source = false;  // one of the sources of the device asked for
};
SetupFirst device_to_set_up_first(const ClientState& client, std::span<const std::uint8_t> payload,
                                  const core::DeviceTable& devices);

// Answers such a DEV request once its device's setup has run elsewhere. When
// it succeeded (`set_up`), the device is held by that setup's subscription and
// the client's own are taken as for any request; when it failed, the client
// is granted 'e' without a second attempt.
PlayerReply answer_device_request_after_setup(ClientState& client,
                                              std::span<const std::uint8_t> payload,
                                              const core::DeviceTable& devices, bool set_up);

}  // namespace playerkit::server
