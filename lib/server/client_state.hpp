#pragma once
// What the server remembers about one client connection, apart from its socket.

#include <cstdint>

#include "core/exchange.hpp"
#include "protocol/constants.hpp"
#include "server/subscription_table.hpp"

namespace playerkit::server {

struct ClientState {
  core::ClientId id = core::kNoClient;
  std::uint16_t port = protocol::kDefaultPort;  // devices are looked up on this port only
  protocol::DataMode mode = protocol::DataMode::kPushNew;
  std::uint16_t frequency = 10;  // data rounds per second in the push modes; 0 stops them
  bool data_requested = false;   // pull modes: a DATA request is waiting for its round
  bool auth_pending = false;     // -k: nothing but an AUTH is accepted yet
  SubscriptionTable subscriptions;

  [[nodiscard]] bool push_mode() const {
    return mode == protocol::DataMode::kPushNew || mode == protocol::DataMode::kPushAll;
  }
  [[nodiscard]] bool new_only() const {
    return mode == protocol::DataMode::kPushNew || mode == protocol::DataMode::kPullNew;
  }
};

}  // namespace playerkit::server
