#pragma once
// One client's view of the devices it has asked for: the access it holds on
// each and, for the NEW data modes, the timestamp of the last sample it got.
//
// Access changes follow 1.5's DEV table (server-behaviour.md §3.1): 'r' and
// 'w' hold one subscription on the device, 'a' holds two, 'c' and 'e' none.
// Entries stay after close, in the order first requested; data rounds walk
// them in that order.

#include <cstdint>
#include <vector>

#include "core/device.hpp"
#include "protocol/constants.hpp"

namespace playerkit::server {

using protocol::Access;
using protocol::DeviceAddress;

class SubscriptionTable {
 public:
  struct Entry {
    DeviceAddress device;
    Access access = Access::kError;
    protocol::Timestamp last_sent;  // timestamp of the last sample sent (NEW modes)
    std::uint64_t last_sequence = 0;  // queued devices: the last sample this client got
  };

  // Moves this client's access on `address` towards `requested`, subscribing
  // to or unsubscribing from `device` (nullptr: no such device on the
  // client's port) as needed, and returns the access now held. A failed
  // subscription leaves the client holding nothing ('e'). Bytes other than
  // r, w, a, c change nothing. On a queued device `reader` is tracked in
  // Device::readers() for as long as it can read.
  Access request(DeviceAddress address, std::uint8_t requested, core::Device* device,
                 core::ClientId reader = core::kNoClient);

  // 'e' for devices never requested.
  [[nodiscard]] Access access(DeviceAddress address) const;
  [[nodiscard]] static bool can_read(Access access) {
    return access == Access::kRead || access == Access::kAll;
  }
  [[nodiscard]] static bool can_write(Access access) {
    return access == Access::kWrite || access == Access::kAll;
  }
  // How many device subscriptions an access letter holds.
  [[nodiscard]] static int held_subscriptions(Access access);

  [[nodiscard]] std::vector<Entry>& entries() { return entries_; }
  [[nodiscard]] const std::vector<Entry>& entries() const { return entries_; }

 private:
  Entry& entry_for(DeviceAddress address);

  std::vector<Entry> entries_;
};

[[nodiscard]] bool is_access_letter(std::uint8_t letter);

}  // namespace playerkit::server
