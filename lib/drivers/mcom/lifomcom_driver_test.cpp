#include "drivers/mcom/lifomcom_driver.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "drivers/test_support.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/mcom.hpp"

namespace playerkit::drivers {
namespace lifomcom_driver_test {

using protocol::kMcomCode;
using protocol::McomConfig;
using protocol::McomReturn;
using protocol::MessageType;

McomConfig mcom_request(std::uint8_t command, std::uint16_t type, std::string_view channel,
                        std::string_view text = "") {
  McomConfig config;
  config.command = command;
  config.type = type;
  config.channel.assign(channel);
  config.data.full = 1;
  config.data.data.assign(text);
  return config;
}

McomConfig capacity_request(std::uint16_t type, std::string_view channel, std::uint8_t capacity) {
  McomConfig config = mcom_request(protocol::kMcomSetCapacityReq, type, channel);
  config.data.data.bytes[0] = static_cast<char>(capacity);
  return config;
}

// "m3"; built by appending because GCC 12 warns (-Wrestrict, a false positive)
// about "m" + std::to_string(i).
std::string numbered(int i) {
  std::string text = "m";
  text += std::to_string(i);
  return text;
}

struct LifomcomTest : ::testing::Test {
  void SetUp() override {
    builtin.load("mcom ( driver \"lifomcom\" )\n");
    device = &builtin.device(kMcomCode);
    ASSERT_TRUE(device->subscribe());
  }

  // One request through the device, as the server's event loop would run it.
  core::Reply ask_bytes(std::vector<std::uint8_t> payload) {
    EXPECT_EQ(device->enqueue_request(testing::make_request(kMcomCode, std::move(payload))),
              core::Device::RequestStatus::kQueued);
    device->update();
    auto replies = device->take_replies();
    EXPECT_EQ(replies.size(), 1u);
    return replies.empty() ? core::Reply{} : replies.front();
  }
  core::Reply ask(const McomConfig& config) { return ask_bytes(protocol::encode(config)); }

  void push(std::uint16_t type, std::string_view channel, std::string_view text) {
    const core::Reply reply = ask(mcom_request(protocol::kMcomPushReq, type, channel, text));
    EXPECT_EQ(reply.type, MessageType::kAck);
    EXPECT_TRUE(reply.payload.empty());
  }
  // The text popped (or read), or "<NACK>" for an empty stack.
  std::string take(std::uint8_t command, std::uint16_t type, std::string_view channel) {
    const core::Reply reply = ask(mcom_request(command, type, channel));
    if (reply.type == MessageType::kNack) {
      EXPECT_TRUE(reply.payload.empty());
      return "<NACK>";
    }
    EXPECT_EQ(reply.type, MessageType::kAck);
    EXPECT_EQ(reply.payload.size(), McomReturn::kWireSize);
    return protocol::decode<McomReturn>(reply.payload).data.data.str();
  }
  std::string pop(std::uint16_t type, std::string_view channel) {
    return take(protocol::kMcomPopReq, type, channel);
  }
  std::string read(std::uint16_t type, std::string_view channel) {
    return take(protocol::kMcomReadReq, type, channel);
  }

  testing::BuiltinDevices builtin;
  core::Device* device = nullptr;
};

TEST(LifomcomSpec, RegisteredAsInManual) {
  const core::DriverSpec spec = lifomcom_driver_spec();
  EXPECT_EQ(spec.name, "lifomcom");
  EXPECT_EQ(spec.interfaces, (std::vector<std::uint16_t>{kMcomCode}));
  EXPECT_EQ(spec.access, protocol::Access::kAll);
  EXPECT_EQ(spec.limits.request_queue, 20u);
}

TEST_F(LifomcomTest, PopAnswersWithTheMcomReturnStruct) {
  push(7, "radio", "hello");
  const core::Reply reply = ask(mcom_request(protocol::kMcomPopReq, 7, "radio"));
  ASSERT_EQ(reply.type, MessageType::kAck);
  ASSERT_EQ(reply.payload.size(), 139u);
  const auto answer = protocol::decode<McomReturn>(reply.payload);
  EXPECT_EQ(answer.type, 7);
  EXPECT_EQ(answer.channel.str(), "radio");
  EXPECT_EQ(answer.data.full, 1);
  EXPECT_EQ(answer.data.data.str(), "hello");
}

TEST_F(LifomcomTest, LastInFirstOutPerChannel) {
  push(1, "radio", "FWD");
  push(1, "radio", "LEFT");
  push(1, "radio", "STOP");
  EXPECT_EQ(pop(1, "radio"), "STOP");
  EXPECT_EQ(pop(1, "radio"), "LEFT");
  EXPECT_EQ(pop(1, "radio"), "FWD");
  EXPECT_EQ(pop(1, "radio"), "<NACK>");
}

TEST_F(LifomcomTest, ChannelsAndTypesAreSeparateStacks) {
  push(1, "radio", "radio 1");
  push(2, "radio", "radio 2");
  push(1, "tv", "tv 1");
  EXPECT_EQ(pop(1, "tv"), "tv 1");
  EXPECT_EQ(pop(1, "tv"), "<NACK>");
  EXPECT_EQ(pop(2, "radio"), "radio 2");
  EXPECT_EQ(pop(1, "radio"), "radio 1");
}

TEST_F(LifomcomTest, ReadLeavesTheMessagePopRemovesIt) {
  push(1, "radio", "keep");
  EXPECT_EQ(read(1, "radio"), "keep");
  EXPECT_EQ(read(1, "radio"), "keep");
  EXPECT_EQ(pop(1, "radio"), "keep");
  EXPECT_EQ(read(1, "radio"), "<NACK>");
}

TEST_F(LifomcomTest, EmptyOrUnknownStackAnswersNackWithoutPayload) {
  EXPECT_EQ(pop(1, "nobody"), "<NACK>");
  EXPECT_EQ(read(1, "nobody"), "<NACK>");
  push(1, "radio", "x");
  EXPECT_EQ(pop(1, "radio"), "x");
  EXPECT_EQ(pop(1, "radio"), "<NACK>");
  EXPECT_EQ(read(1, "radio"), "<NACK>");
}

TEST_F(LifomcomTest, FullStackOfTenDropsTheOldest) {
  for (int i = 0; i < 11; ++i) push(1, "radio", numbered(i));
  for (int i = 10; i >= 1; --i) EXPECT_EQ(pop(1, "radio"), numbered(i));
  EXPECT_EQ(pop(1, "radio"), "<NACK>");  // m0 was dropped by the eleventh push
}

TEST_F(LifomcomTest, SetCapacityTakesTheFirstDataByte) {
  EXPECT_EQ(ask(capacity_request(1, "radio", 3)).type, MessageType::kAck);
  for (int i = 0; i < 5; ++i) push(1, "radio", numbered(i));
  EXPECT_EQ(pop(1, "radio"), "m4");
  EXPECT_EQ(pop(1, "radio"), "m3");
  EXPECT_EQ(pop(1, "radio"), "m2");
  EXPECT_EQ(pop(1, "radio"), "<NACK>");
  push(1, "tv", "other stacks keep ten");
  EXPECT_EQ(pop(1, "tv"), "other stacks keep ten");
}

TEST_F(LifomcomTest, SetCapacityIsBoundedByTheTenSlotArray) {
  const core::Reply reply = ask(capacity_request(1, "radio", 200));
  EXPECT_EQ(reply.type, MessageType::kAck);
  EXPECT_TRUE(reply.payload.empty());
  for (int i = 0; i < 12; ++i) push(1, "radio", numbered(i));
  int popped = 0;
  while (pop(1, "radio") != "<NACK>" && popped < 20) ++popped;
  EXPECT_EQ(popped, 10);
}

TEST_F(LifomcomTest, SetCapacityZeroIsRefused) {
  EXPECT_EQ(ask(capacity_request(1, "radio", 0)).type, MessageType::kNack);
  for (int i = 0; i < 3; ++i) push(1, "radio", numbered(i));
  EXPECT_EQ(pop(1, "radio"), "m2");  // the stack still works with its default capacity
}

TEST_F(LifomcomTest, ClearEmptiesOnlyThatStack) {
  push(1, "radio", "a");
  push(1, "radio", "b");
  push(1, "tv", "c");
  const core::Reply reply = ask(mcom_request(protocol::kMcomClearReq, 1, "radio"));
  EXPECT_EQ(reply.type, MessageType::kAck);
  EXPECT_TRUE(reply.payload.empty());
  EXPECT_EQ(pop(1, "radio"), "<NACK>");
  EXPECT_EQ(pop(1, "tv"), "c");
  EXPECT_EQ(ask(mcom_request(protocol::kMcomClearReq, 9, "nobody")).type, MessageType::kAck);
}

TEST_F(LifomcomTest, UnknownCommandIsNacked) {
  for (std::uint8_t command : {std::uint8_t{5}, std::uint8_t{99}, std::uint8_t{255}}) {
    const core::Reply reply = ask(mcom_request(command, 1, "radio", "x"));
    EXPECT_EQ(reply.type, MessageType::kNack) << int{command};
    EXPECT_TRUE(reply.payload.empty());
  }
  EXPECT_EQ(pop(1, "radio"), "<NACK>");  // nothing was pushed by them
}

TEST_F(LifomcomTest, RequestsThatAreNot140BytesAreNacked) {
  const auto valid = protocol::encode(mcom_request(protocol::kMcomPushReq, 1, "radio", "x"));
  ASSERT_EQ(valid.size(), 140u);
  const std::vector<std::vector<std::uint8_t>> wrong{
      {}, {protocol::kMcomPushReq}, {valid.begin(), valid.end() - 1}};
  for (const auto& payload : wrong) {
    EXPECT_EQ(ask_bytes(payload).type, MessageType::kNack) << payload.size() << " bytes";
  }
  auto longer = valid;
  longer.push_back(0);
  EXPECT_EQ(ask_bytes(longer).type, MessageType::kNack);
  EXPECT_EQ(pop(1, "radio"), "<NACK>");
}

TEST_F(LifomcomTest, StoredSlotIsFullAndKeepsEveryDataByte) {
  McomConfig config = mcom_request(protocol::kMcomPushReq, 1, "radio");
  config.data.full = 0;  // 1.5 marked a pushed slot full whatever the client said
  for (std::size_t i = 0; i < config.data.data.bytes.size(); ++i) {
    config.data.data.bytes[i] = static_cast<char>(i * 3 + 1);  // binary, no NUL
  }
  ASSERT_EQ(ask(config).type, MessageType::kAck);
  const core::Reply reply = ask(mcom_request(protocol::kMcomPopReq, 1, "radio"));
  ASSERT_EQ(reply.type, MessageType::kAck);
  const auto answer = protocol::decode<McomReturn>(reply.payload);
  EXPECT_EQ(answer.data.full, 1);
  EXPECT_EQ(answer.data.data.bytes, config.data.data.bytes);
}

TEST_F(LifomcomTest, ChannelNameEndsAtItsFirstNul) {
  McomConfig push_request = mcom_request(protocol::kMcomPushReq, 1, "ab", "m");
  push_request.channel.bytes = {'a', 'b', '\0', 'x', 'y', 'z', '\0', '\0'};
  ASSERT_EQ(ask(push_request).type, MessageType::kAck);
  const core::Reply reply = ask(mcom_request(protocol::kMcomPopReq, 1, "ab"));
  ASSERT_EQ(reply.type, MessageType::kAck);
  const auto answer = protocol::decode<McomReturn>(reply.payload);
  // Same stack as plain "ab"; the reply's name is zero-padded, no stray bytes.
  EXPECT_EQ(answer.channel.bytes, (std::array<char, 8>{'a', 'b', 0, 0, 0, 0, 0, 0}));
}

TEST_F(LifomcomTest, MessagesOutliveTheSubscription) {
  push(1, "radio", "left behind");
  device->unsubscribe();
  ASSERT_EQ(device->subscriptions(), 0);
  ASSERT_TRUE(device->subscribe());
  EXPECT_EQ(pop(1, "radio"), "left behind");
}

TEST_F(LifomcomTest, QueueHoldsTwentyRequests) {
  const auto request = protocol::encode(mcom_request(protocol::kMcomPushReq, 1, "radio", "q"));
  for (int i = 0; i < 20; ++i) {
    ASSERT_EQ(device->enqueue_request(testing::make_request(kMcomCode, request)),
              core::Device::RequestStatus::kQueued);
  }
  EXPECT_EQ(device->enqueue_request(testing::make_request(kMcomCode, request)),
            core::Device::RequestStatus::kQueueFull);
  device->update();
  const auto replies = device->take_replies();
  ASSERT_EQ(replies.size(), 20u);
  EXPECT_TRUE(std::all_of(replies.begin(), replies.end(),
                          [](const core::Reply& r) { return r.type == MessageType::kAck; }));
}

TEST_F(LifomcomTest, PublishesNoData) {
  push(1, "radio", "x");
  device->update();
  EXPECT_EQ(device->latest_data()->sequence, 0u);
}

}  // namespace lifomcom_driver_test
}  // namespace playerkit::drivers
