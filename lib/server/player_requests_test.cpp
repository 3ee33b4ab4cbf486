#include "server/player_requests.hpp"

#include <gtest/gtest.h>

#include "core/test_drivers.hpp"
#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/player.hpp"

namespace playerkit::server {
namespace player_requests_test {

using protocol::MessageType;
using Bytes = std::vector<std::uint8_t>;

struct PlayerRequestsFixture : ::testing::Test {
  void SetUp() override {
    logger.set_sink([](core::LogLevel, std::string_view) {});
    add(6665, protocol::kPositionCode, 0, "bob", "p2os_position");
    add(6665, protocol::kLaserCode, 0, "bob", "sicklms200");
    add(6666, protocol::kLaserCode, 0, "alice", "readlog");
    client.port = 6665;
  }
  void add(std::uint16_t port, std::uint16_t code, std::uint16_t index, std::string robot,
           std::string driver) {
    devices.add(std::make_unique<core::Device>(
        core::DeviceKey{port, {code, index}},
        core::DeviceInfo{std::move(driver), std::move(robot), Access::kAll, {}, false},
        std::make_unique<core::testing::CountingDriver>(counts), clock, logger));
  }
  PlayerReply ask(const Bytes& payload) { return answer_player_request(client, payload, devices); }

  core::testing::CallCounts counts;
  core::ManualClock clock;
  core::Logger logger;
  core::DeviceTable devices;
  ClientState client;
};

TEST_F(PlayerRequestsFixture, DeviceListIs388BytesOfThisPortsDevicesInOrder) {
  const auto reply = ask({0, 1});
  EXPECT_EQ(reply.type, MessageType::kAck);
  ASSERT_EQ(reply.payload.size(), 388u);
  const Bytes head(reply.payload.begin(), reply.payload.begin() + 16);
  EXPECT_EQ(head, (Bytes{0, 1, 0, 2,                 // subtype, count
                         0, 4, 0, 0, 0x1A, 0x09,     // position:0 port 6665
                         0, 6, 0, 0, 0x1A, 0x09}));  // laser:0 port 6665
  EXPECT_TRUE(std::all_of(reply.payload.begin() + 16, reply.payload.end(),
                          [](std::uint8_t b) { return b == 0; }));
}

TEST_F(PlayerRequestsFixture, ShortPayloadAndUnknownSubtypesAreRefused) {
  EXPECT_EQ(ask({}).type, MessageType::kNack);
  EXPECT_EQ(ask({0}).type, MessageType::kNack);
  EXPECT_EQ(ask({0, 99}).type, MessageType::kNack);
  EXPECT_EQ(ask({0, 7, 'k'}).type, MessageType::kNack);  // AUTH when none is pending
}

TEST_F(PlayerRequestsFixture, DriverInfoNamesTheDriverOnTheGivenPort) {
  auto reply = ask({0, 2, 0, 6, 0, 0, 0x1A, 0x0A});  // laser:0 on 6666
  EXPECT_EQ(reply.type, MessageType::kAck);
  auto info = protocol::decode<protocol::DriverInfo>(reply.payload);
  EXPECT_EQ(info.driver_name.view(), "readlog");
  EXPECT_EQ(info.id.port, 6666);
  reply = ask({0, 2, 0, 6, 0, 0, 0x1A, 0x0B});  // nothing on 6667
  info = protocol::decode<protocol::DriverInfo>(reply.payload);
  EXPECT_EQ(info.driver_name.view(), "unknown");
}

TEST_F(PlayerRequestsFixture, DevRequestOpensAndRepliesWith71Bytes) {
  const auto reply = ask({0, 3, 0, 6, 0, 0, 'r'});
  EXPECT_EQ(reply.type, MessageType::kAck);
  ASSERT_EQ(reply.payload.size(), 71u);
  EXPECT_EQ(Bytes(reply.payload.begin(), reply.payload.begin() + 7), (Bytes{0, 3, 0, 6, 0, 0, 'r'}));
  EXPECT_EQ(protocol::decode<protocol::DeviceAccessReply>(reply.payload).driver_name.view(), "sicklms200");
  EXPECT_EQ(devices.find(6665, {protocol::kLaserCode, 0})->subscriptions(), 1);
  EXPECT_EQ(client.subscriptions.access({protocol::kLaserCode, 0}), Access::kRead);
}

TEST_F(PlayerRequestsFixture, DevRequestForADeviceOfAnotherPortGivesEAndNoName) {
  client.port = 6666;
  const auto reply = ask({0, 3, 0, 4, 0, 0, 'r'});  // position:0 is on 6665 only
  EXPECT_EQ(reply.type, MessageType::kAck);
  const auto access = protocol::decode<protocol::DeviceAccessReply>(reply.payload);
  EXPECT_EQ(access.access, 'e');
  EXPECT_EQ(access.driver_name.view(), "");
}

TEST_F(PlayerRequestsFixture, ShortDevRequestIsNackedWithTheFullStruct) {
  const auto reply = ask({0, 3, 0, 6, 0});
  EXPECT_EQ(reply.type, MessageType::kNack);
  EXPECT_EQ(reply.payload.size(), 71u);
  EXPECT_EQ(devices.find(6665, {protocol::kLaserCode, 0})->subscriptions(), 0);
}

TEST_F(PlayerRequestsFixture, DataRequestOnlyInPullModes) {
  EXPECT_EQ(ask({0, 4}).type, MessageType::kNack);  // default PUSH_NEW
  auto reply = ask({0, 5, 3});                        // PULL_NEW
  EXPECT_EQ(reply.type, MessageType::kAck);
  EXPECT_TRUE(reply.schedule_changed);
  EXPECT_EQ(client.mode, protocol::DataMode::kPullNew);
  reply = ask({0, 4});
  EXPECT_EQ(reply.type, MessageType::kAck);
  EXPECT_TRUE(reply.round_requested);
  EXPECT_TRUE(client.data_requested);
  EXPECT_EQ(ask({0, 4, 0}).type, MessageType::kNack);  // must be exactly 2 bytes
  ask({0, 5, 1});  // switching to a pull mode clears the request
  EXPECT_FALSE(client.data_requested);
}

TEST_F(PlayerRequestsFixture, DataModeAndFrequencyMustHaveExactSizes) {
  EXPECT_EQ(ask({0, 5}).type, MessageType::kNack);
  EXPECT_EQ(ask({0, 5, 0, 0}).type, MessageType::kNack);
  EXPECT_EQ(ask({0, 5, 4}).type, MessageType::kNack);
  EXPECT_EQ(client.mode, protocol::DataMode::kPushNew);
  EXPECT_EQ(ask({0, 6, 0}).type, MessageType::kNack);
  EXPECT_EQ(ask({0, 6, 0, 50, 0}).type, MessageType::kNack);
  EXPECT_EQ(ask({0, 6, 0x01, 0x2C}).type, MessageType::kAck);
  EXPECT_EQ(client.frequency, 300);
}

TEST_F(PlayerRequestsFixture, NameServiceFindsARobotOnAnyPort) {
  protocol::NameServiceRequest request;
  request.subtype = protocol::kPlayerNameserviceReq;
  request.name = "alice";
  auto reply = ask(protocol::encode(request));
  EXPECT_EQ(reply.type, MessageType::kAck);
  ASSERT_EQ(reply.payload.size(), 68u);
  EXPECT_EQ(reply.payload[0], 0);  // subtype big-endian (1.5: host order, 08 00)
  EXPECT_EQ(reply.payload[1], 8);
  auto answer = protocol::decode<protocol::NameServiceRequest>(reply.payload);
  EXPECT_EQ(answer.name.view(), "alice");
  EXPECT_EQ(answer.port, 6666);
  request.name = "Alice";
  answer = protocol::decode<protocol::NameServiceRequest>(ask(protocol::encode(request)).payload);
  EXPECT_EQ(answer.port, 0);
}

}  // namespace player_requests_test
}  // namespace playerkit::server
