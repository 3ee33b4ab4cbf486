#include "drivers/null/null_driver.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "drivers/test_support.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"

namespace playerkit::drivers {
namespace null_driver_test {

using protocol::kNullCode;
using protocol::MessageType;
using testing::make_request;

struct NullDriverTest : ::testing::Test {
  void SetUp() override { builtin.load("null ( driver \"null\" )\n"); }
  testing::BuiltinDevices builtin;
};

TEST_F(NullDriverTest, RegisteredForTheNullInterfaceReadOnly) {
  const core::DriverSpec spec = null_driver_spec();
  EXPECT_EQ(spec.name, "null");
  EXPECT_EQ(spec.interfaces, (std::vector<std::uint16_t>{kNullCode}));
  EXPECT_EQ(spec.access, protocol::Access::kRead);
  EXPECT_FALSE(spec.summary.empty());
}

TEST_F(NullDriverTest, SubscribesAndNeverPublishes) {
  core::Device& device = builtin.device(kNullCode);
  ASSERT_TRUE(device.subscribe());
  for (int round = 0; round < 5; ++round) device.update();
  EXPECT_EQ(device.latest_data()->sequence, 0u);
  device.unsubscribe();
  EXPECT_EQ(device.subscriptions(), 0);
}

TEST_F(NullDriverTest, AnswersEveryRequestNackWithNoPayload) {
  core::Device& device = builtin.device(kNullCode);
  ASSERT_TRUE(device.subscribe());
  const std::vector<std::vector<std::uint8_t>> requests{{0}, {1, 2, 3}, {255}, {}};
  for (const auto& payload : requests) {
    ASSERT_EQ(device.enqueue_request(make_request(kNullCode, payload)),
              core::Device::RequestStatus::kQueued);
  }
  device.update();
  const auto replies = device.take_replies();
  ASSERT_EQ(replies.size(), requests.size());
  for (const core::Reply& reply : replies) {
    EXPECT_EQ(reply.type, MessageType::kNack);
    EXPECT_TRUE(reply.payload.empty());
    EXPECT_EQ(reply.client, 1u);
    EXPECT_EQ(reply.device, (protocol::DeviceAddress{kNullCode, 0}));
  }
}

TEST_F(NullDriverTest, AcceptsNoCommands) {
  core::Device& device = builtin.device(kNullCode);
  ASSERT_TRUE(device.subscribe());
  const std::vector<std::uint8_t> anything{1, 2, 3};
  EXPECT_EQ(device.put_command(1, anything), core::Device::CommandStatus::kReadOnly);
  EXPECT_FALSE(device.take_command().has_value());
}

}  // namespace null_driver_test
}  // namespace playerkit::drivers
