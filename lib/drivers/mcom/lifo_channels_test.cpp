#include "drivers/mcom/lifo_channels.hpp"

#include <gtest/gtest.h>

#include <string>

namespace playerkit::drivers {
namespace lifo_channels_test {

protocol::McomData message(std::string_view text) {
  protocol::McomData data;
  data.full = 1;
  data.data.assign(text);
  return data;
}

std::string text_of(const std::optional<protocol::McomData>& data) {
  return data ? data->data.str() : "<none>";
}

const ChannelKey kRadio{1, "radio"};

TEST(LifoChannels, PopsNewestFirst) {
  LifoChannels channels;
  channels.push(kRadio, message("a"));
  channels.push(kRadio, message("b"));
  channels.push(kRadio, message("c"));
  EXPECT_EQ(text_of(channels.pop(kRadio)), "c");
  EXPECT_EQ(text_of(channels.pop(kRadio)), "b");
  EXPECT_EQ(text_of(channels.pop(kRadio)), "a");
  EXPECT_FALSE(channels.pop(kRadio).has_value());
}

TEST(LifoChannels, ReadLeavesTheMessage) {
  LifoChannels channels;
  channels.push(kRadio, message("a"));
  EXPECT_EQ(text_of(channels.read(kRadio)), "a");
  EXPECT_EQ(text_of(channels.read(kRadio)), "a");
  EXPECT_EQ(channels.size(kRadio), 1u);
}

TEST(LifoChannels, UnknownStackIsEmptyWithDefaultCapacity) {
  const LifoChannels channels;
  EXPECT_FALSE(channels.read(kRadio).has_value());
  EXPECT_EQ(channels.size(kRadio), 0u);
  EXPECT_EQ(channels.capacity(kRadio), 10u);
}

TEST(LifoChannels, TypeAndChannelNameBothSelectTheStack) {
  LifoChannels channels;
  channels.push({1, "radio"}, message("type 1"));
  channels.push({2, "radio"}, message("type 2"));
  channels.push({1, "tv"}, message("tv"));
  EXPECT_EQ(text_of(channels.pop({2, "radio"})), "type 2");
  EXPECT_FALSE(channels.pop({2, "radio"}).has_value());
  EXPECT_EQ(text_of(channels.pop({1, "radio"})), "type 1");
  EXPECT_EQ(text_of(channels.pop({1, "tv"})), "tv");
}

TEST(LifoChannels, FullStackDropsItsOldestMessage) {
  LifoChannels channels;
  for (int i = 0; i < 12; ++i) channels.push(kRadio, message(std::to_string(i)));
  EXPECT_EQ(channels.size(kRadio), 10u);
  for (int i = 11; i >= 2; --i) EXPECT_EQ(text_of(channels.pop(kRadio)), std::to_string(i));
  EXPECT_FALSE(channels.pop(kRadio).has_value());  // 0 and 1 were dropped
}

TEST(LifoChannels, SmallerCapacityKeepsTheNewest) {
  LifoChannels channels;
  for (int i = 0; i < 5; ++i) channels.push(kRadio, message(std::to_string(i)));
  channels.set_capacity(kRadio, 2);
  EXPECT_EQ(channels.capacity(kRadio), 2u);
  EXPECT_EQ(channels.size(kRadio), 2u);
  channels.push(kRadio, message("5"));
  EXPECT_EQ(text_of(channels.pop(kRadio)), "5");
  EXPECT_EQ(text_of(channels.pop(kRadio)), "4");
  EXPECT_FALSE(channels.pop(kRadio).has_value());
}

TEST(LifoChannels, CapacitySetBeforeTheFirstPushApplies) {
  LifoChannels channels;
  channels.set_capacity(kRadio, 1);
  channels.push(kRadio, message("old"));
  channels.push(kRadio, message("new"));
  EXPECT_EQ(channels.size(kRadio), 1u);
  EXPECT_EQ(text_of(channels.read(kRadio)), "new");
}

TEST(LifoChannels, ClearEmptiesOneStackAndKeepsItsCapacity) {
  LifoChannels channels;
  const ChannelKey other{1, "tv"};
  channels.set_capacity(kRadio, 3);
  channels.push(kRadio, message("a"));
  channels.push(other, message("b"));
  channels.clear(kRadio);
  EXPECT_EQ(channels.size(kRadio), 0u);
  EXPECT_EQ(channels.capacity(kRadio), 3u);
  EXPECT_EQ(text_of(channels.read(other)), "b");
  channels.clear({9, "nothing"});  // unknown: nothing happens
  EXPECT_EQ(channels.size({9, "nothing"}), 0u);
}

}  // namespace lifo_channels_test
}  // namespace playerkit::drivers
