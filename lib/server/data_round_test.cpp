#include "server/data_round.hpp"

#include <gtest/gtest.h>

#include "core/test_drivers.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::server {
namespace data_round_test {

using protocol::MessageType;
using Bytes = std::vector<std::uint8_t>;

std::vector<protocol::Message> split(const Bytes& bytes) {
  std::vector<protocol::Message> messages;
  std::size_t offset = 0;
  while (offset < bytes.size()) {
    auto parsed = protocol::parse_message(std::span(bytes).subspan(offset));
    if (!parsed) break;
    messages.push_back(parsed->message);
    offset += parsed->consumed;
  }
  EXPECT_EQ(offset, bytes.size());
  return messages;
}

struct DataRoundFixture : ::testing::Test {
  void SetUp() override {
    logger.set_sink([](core::LogLevel, std::string_view) {});
    sonar = &add(protocol::kSonarCode, Access::kRead);
    laser = &add(protocol::kLaserCode, Access::kRead);
    position = &add(protocol::kPositionCode, Access::kWrite);  // registered write-only
    client.port = 6665;
  }
  core::Device& add(std::uint16_t code, Access registered) {
    return devices.add(std::make_unique<core::Device>(
        core::DeviceKey{6665, {code, 0}}, core::DeviceInfo{"counting", "", registered, {}, false},
        std::make_unique<core::testing::CountingDriver>(counts), clock, logger));
  }
  void open(core::Device& device, char access) {
    client.subscriptions.request(device.address(), static_cast<std::uint8_t>(access), &device);
  }

  core::testing::CallCounts counts;
  core::ManualClock clock;
  core::Logger logger;
  core::DeviceTable devices;
  ClientState client;
  core::Device* sonar = nullptr;
  core::Device* laser = nullptr;
  core::Device* position = nullptr;
};

TEST_F(DataRoundFixture, EmptyRoundIsExactlyOneSynch) {
  const auto round = build_data_round(client, devices, {42, 7});
  EXPECT_EQ(round.data_messages, 0u);
  EXPECT_EQ(round.bytes, (Bytes{0x58, 0x78, 0, 5, 0, 1, 0, 0,   // stx, SYNCH, player:0
                                0, 0, 0, 42, 0, 0, 0, 7,        // time
                                0, 0, 0, 42, 0, 0, 0, 7,        // timestamp
                                0, 0, 0, 0, 0, 0, 0, 0}));      // reserved, size
}

TEST_F(DataRoundFixture, SendsReadableDevicesInSubscriptionOrderThenSynch) {
  open(*laser, 'r');
  open(*sonar, 'a');
  open(*position, 'a');  // write-only driver: never data
  laser->publish({1, 2, 3}, {10, 0});
  sonar->publish({9}, {11, 0});
  position->publish({7}, {12, 0});
  const auto messages = split(build_data_round(client, devices, {20, 0}).bytes);
  ASSERT_EQ(messages.size(), 3u);
  EXPECT_EQ(messages[0].type(), MessageType::kData);
  EXPECT_EQ(messages[0].device().interface, protocol::kLaserCode);
  EXPECT_EQ(messages[0].payload, (Bytes{1, 2, 3}));
  EXPECT_EQ(messages[0].time(), (protocol::Timestamp{20, 0}));
  EXPECT_EQ(messages[0].timestamp(), (protocol::Timestamp{10, 0}));
  EXPECT_EQ(messages[1].device().interface, protocol::kSonarCode);
  EXPECT_EQ(messages[2].type(), MessageType::kSynch);
}

TEST_F(DataRoundFixture, AHandedBackVectorIsReusedWithoutItsOldBytes) {
  open(*laser, 'r');
  client.mode = protocol::DataMode::kPushAll;
  laser->publish(Bytes(1000, 0xab), {10, 0});
  DataRound first = build_data_round(client, devices, {20, 0});
  const Bytes first_bytes = first.bytes;
  const std::uint8_t* storage = first.bytes.data();
  DataRound second = build_data_round(client, devices, {20, 0}, std::move(first.bytes));
  EXPECT_EQ(second.bytes.data(), storage);  // same capacity needed: no new allocation
  EXPECT_EQ(second.bytes, first_bytes);     // and nothing of the old round appended twice
  EXPECT_EQ(split(second.bytes).size(), 2u);
}

TEST_F(DataRoundFixture, NewModesSkipDataAlreadySentAllModesResend) {
  open(*laser, 'r');
  open(*sonar, 'w');  // write access: no data
  laser->publish({1}, {10, 0});
  sonar->publish({2}, {10, 0});
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 1u);
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 0u);
  laser->publish({1}, {10, 500});
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 1u);
  client.mode = protocol::DataMode::kPushAll;
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 1u);
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 1u);
}

TEST_F(DataRoundFixture, NothingBeforeTheFirstPublishEvenInAllModes) {
  client.mode = protocol::DataMode::kPullAll;
  open(*laser, 'r');
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 0u);
}

TEST_F(DataRoundFixture, ClosedDevicesStopSending) {
  open(*laser, 'r');
  laser->publish({1}, {10, 0});
  open(*laser, 'c');
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 0u);
}


}  // namespace data_round_test
}  // namespace playerkit::server

namespace playerkit::server {
namespace data_round_test {

TEST_F(DataRoundFixture, QueuedDeviceSendsEveryMessageOnceFromSubscriptionOn) {
  core::Device& comms = devices.add(std::make_unique<core::Device>(
      core::DeviceKey{6665, {protocol::kCommsCode, 0}},
      core::DeviceInfo{"queued", "", Access::kAll, core::DeviceLimits{1, 8}, false},
      std::make_unique<core::testing::CountingDriver>(counts), clock, logger));
  comms.publish({0}, {1, 0});  // before the client subscribed: not for it
  open(comms, 'r');
  comms.publish({1}, {2, 0});
  comms.publish({2}, {2, 0});  // same timestamp: still a new message
  comms.publish({3}, {3, 0});
  auto messages = split(build_data_round(client, devices, {}).bytes);
  ASSERT_EQ(messages.size(), 4u);
  EXPECT_EQ(messages[0].payload, (Bytes{1}));
  EXPECT_EQ(messages[1].payload, (Bytes{2}));
  EXPECT_EQ(messages[2].payload, (Bytes{3}));
  client.mode = protocol::DataMode::kPushAll;  // messages are not repeated in ALL modes
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 0u);
  comms.publish({4}, {4, 0});
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 1u);
}


TEST_F(DataRoundFixture, QueuedDeviceLearnsHowFarEachReaderGot) {
  core::Device& comms = devices.add(std::make_unique<core::Device>(
      core::DeviceKey{6665, {protocol::kCommsCode, 0}},
      core::DeviceInfo{"queued", "", Access::kAll, core::DeviceLimits{1, 8}, false},
      std::make_unique<core::testing::CountingDriver>(counts), clock, logger));
  comms.publish({0}, {1, 0});
  client.id = 42;
  client.subscriptions.request(comms.address(), 'r', &comms, client.id);
  EXPECT_EQ(comms.readers().count(), 1u);
  std::stop_source never;
  // Registered at sample 1 (published before it subscribed): nothing owed yet.
  EXPECT_TRUE(comms.readers().wait_until_taken(1, never.get_token()));
  comms.publish({1}, {2, 0});
  comms.publish({2}, {3, 0});
  std::stop_source stopped;
  stopped.request_stop();
  EXPECT_FALSE(comms.readers().wait_until_taken(3, stopped.get_token()));  // not sent yet
  EXPECT_EQ(build_data_round(client, devices, {}).data_messages, 2u);
  EXPECT_TRUE(comms.readers().wait_until_taken(3, stopped.get_token()));
  client.subscriptions.request(comms.address(), 'c', &comms, client.id);
  EXPECT_EQ(comms.readers().count(), 0u);  // closing lets the publisher go on
}

}  // namespace data_round_test
}  // namespace playerkit::server
