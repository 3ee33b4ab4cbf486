#pragma once
// One data round for one client: a DATA message per subscribed device that has
// something to send, then exactly one SYNCH (server-behaviour.md §4). The
// round goes out as one write.

#include <cstdint>
#include <vector>

#include "core/device_table.hpp"
#include "server/client_state.hpp"

namespace playerkit::server {

struct DataRound {
  std::vector<std::uint8_t> bytes;
  std::size_t data_messages = 0;  // besides the SYNCH
};

// Walks the client's subscriptions in order. A device is included when the
// client may read it, the driver registered read access and it has published;
// in the NEW modes only if its timestamp differs from the last one this client
// got (which is then remembered). Devices that queue data (comms) send every
// sample this client has not had yet, oldest first. Header time is `now`.
// `storage` becomes the round's bytes (its contents dropped, its capacity
// kept): a session hands back its last round's vector so that a round at
// 100 Hz costs no allocation.
DataRound build_data_round(ClientState& client, const core::DeviceTable& devices,
                           protocol::Timestamp now, std::vector<std::uint8_t> storage = {});

}  // namespace playerkit::server
