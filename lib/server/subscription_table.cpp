#include "server/subscription_table.hpp"

#include <algorithm>

namespace playerkit::server {

bool is_access_letter(std::uint8_t letter) {
  return letter == 'r' || letter == 'w' || letter == 'a' || letter == 'c';
}

int SubscriptionTable::held_subscriptions(Access access) {
  switch (access) {
    case Access::kRead:
    case Access::kWrite: return 1;
    case Access::kAll: return 2;
    case Access::kClose:
    case Access::kError: return 0;
  }
  return 0;
}

SubscriptionTable::Entry& SubscriptionTable::entry_for(DeviceAddress address) {
  auto it = std::find_if(entries_.begin(), entries_.end(),
                         [&](const Entry& e) { return e.device == address; });
  if (it != entries_.end()) return *it;
  entries_.push_back(Entry{address, Access::kError, {}});
  return entries_.back();
}

Access SubscriptionTable::access(DeviceAddress address) const {
  auto it = std::find_if(entries_.begin(), entries_.end(),
                         [&](const Entry& e) { return e.device == address; });
  return it == entries_.end() ? Access::kError : it->access;
}

Access SubscriptionTable::request(DeviceAddress address, std::uint8_t requested, core::Device* device,
                                  core::ClientId reader) {
  Entry& entry = entry_for(address);
  if (!is_access_letter(requested)) return entry.access;
  const auto wanted = static_cast<Access>(requested);
  const int held = held_subscriptions(entry.access);
  const int needed = held_subscriptions(wanted);
  const bool starts_reading = !can_read(entry.access) && can_read(wanted) && device != nullptr;
  const bool stops_reading = can_read(entry.access) && !can_read(wanted) && device != nullptr;

  // A queued device's messages reach a client from the moment it can read:
  // mark the place before the subscription starts the driver publishing.
  if (starts_reading) {
    entry.last_sequence = device->latest_data()->sequence;
    if (device->queues_data()) device->readers().taken(reader, entry.last_sequence);
  }
  for (int i = held; i < needed; ++i) {
    if (device == nullptr || !device->subscribe()) {
      // 1.5 kept (leaked) what was held before; give it all back instead.
      for (int j = 0; j < i && device != nullptr; ++j) device->unsubscribe_from_event_loop();
      if (device != nullptr) device->readers().forget(reader);
      entry.access = Access::kError;
      return entry.access;
    }
  }
  if (stops_reading) device->readers().forget(reader);
  for (int i = needed; i < held && device != nullptr; ++i) device->unsubscribe_from_event_loop();
  // Closing what was never open keeps 'e' (or 'c'), as 1.5 did.
  if (!(wanted == Access::kClose && held == 0)) entry.access = wanted;
  return entry.access;
}

}  // namespace playerkit::server
