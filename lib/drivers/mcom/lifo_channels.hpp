#pragma once
// The message stacks behind the lifomcom driver. 1.5 kept one stack per
// (type, channel name) pair: a pop on channel "a" with type 2 never sees what
// was pushed on "a" with type 1. Each stack holds at most its capacity
// (MCOM_N_BUFS = 10 by default); pushing onto a full stack drops the oldest
// message, as 1.5's ring buffer overwrote its oldest slot.

#include <compare>
#include <cstddef>
#include <cstdint>
#include <deque>
#include <map>
#include <optional>
#include <string>

#include "protocol/messages/mcom.hpp"

namespace playerkit::drivers {

struct ChannelKey {
  std::uint16_t type = 0;
  std::string channel;  // the name up to its first NUL, as 1.5 compared it (strcmp)

  friend auto operator<=>(const ChannelKey&, const ChannelKey&) = default;
};

class LifoChannels {
 public:
  static constexpr std::size_t kDefaultCapacity = protocol::kMcomNBufs;
  // 1.5 stored each stack in an array of MCOM_N_BUFS slots; larger capacities
  // ran past it.
  static constexpr std::size_t kMaxCapacity = protocol::kMcomNBufs;

  // Stores `message` on top, dropping the oldest message if the stack is full.
  void push(const ChannelKey& key, const protocol::McomData& message);
  // The newest message, removed; nullopt when the stack is empty.
  std::optional<protocol::McomData> pop(const ChannelKey& key);
  // The newest message, left in place; nullopt when the stack is empty.
  [[nodiscard]] std::optional<protocol::McomData> read(const ChannelKey& key) const;
  // Drops every message of the stack; its capacity stays.
  void clear(const ChannelKey& key);
  // Creates the stack if needed. Requires 1 <= capacity <= kMaxCapacity; when
  // the stack holds more, the oldest messages go.
  void set_capacity(const ChannelKey& key, std::size_t capacity);

  [[nodiscard]] std::size_t size(const ChannelKey& key) const;
  [[nodiscard]] std::size_t capacity(const ChannelKey& key) const;

 private:
  struct Stack {
    std::deque<protocol::McomData> messages;  // oldest at the front, newest at the back
    std::size_t capacity = kDefaultCapacity;

    void trim_to_capacity();
  };

  [[nodiscard]] const Stack* find(const ChannelKey& key) const;

  std::map<ChannelKey, Stack> stacks_;
};

}  // namespace playerkit::drivers
