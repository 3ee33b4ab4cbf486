#include "drivers/mcom/lifo_channels.hpp"

#include <cassert>

namespace playerkit::drivers {

void LifoChannels::Stack::trim_to_capacity() {
  while (messages.size() > capacity) messages.pop_front();
}

void LifoChannels::push(const ChannelKey& key, const protocol::McomData& message) {
  Stack& stack = stacks_[key];
  stack.messages.push_back(message);
  stack.trim_to_capacity();
}

std::optional<protocol::McomData> LifoChannels::pop(const ChannelKey& key) {
  const auto found = stacks_.find(key);
  if (found == stacks_.end() || found->second.messages.empty()) return std::nullopt;
  protocol::McomData newest = found->second.messages.back();
  found->second.messages.pop_back();
  return newest;
}

std::optional<protocol::McomData> LifoChannels::read(const ChannelKey& key) const {
  const Stack* stack = find(key);
  if (stack == nullptr || stack->messages.empty()) return std::nullopt;
  return stack->messages.back();
}

void LifoChannels::clear(const ChannelKey& key) {
  if (const auto found = stacks_.find(key); found != stacks_.end()) found->second.messages.clear();
}

void LifoChannels::set_capacity(const ChannelKey& key, std::size_t capacity) {
  assert(capacity >= 1 && capacity <= kMaxCapacity);
  Stack& stack = stacks_[key];
  stack.capacity = capacity;
  stack.trim_to_capacity();
}

std::size_t LifoChannels::size(const ChannelKey& key) const {
  const Stack* stack = find(key);
  return stack == nullptr ? 0 : stack->messages.size();
}

std::size_t LifoChannels::capacity(const ChannelKey& key) const {
  const Stack* stack = find(key);
  return stack == nullptr ? kDefaultCapacity : stack->capacity;
}

const LifoChannels::Stack* LifoChannels::find(const ChannelKey& key) const {
  const auto found = stacks_.find(key);
  return found == stacks_.end() ? nullptr : &found->second;
}

}  // namespace playerkit::drivers
