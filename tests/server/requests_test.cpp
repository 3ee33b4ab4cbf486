// Requests to devices, commands and what a disconnect leaves behind.

#include <gtest/gtest.h>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/position.hpp"
#include "support/raw_client.hpp"
#include "test_server.hpp"

namespace playerkit::testing {
namespace requests_test {

using protocol::MessageType;
using Bytes = std::vector<std::uint8_t>;

constexpr const char* kConfig =
    "position:0 ( driver \"actuator\" )\n"
    "laser:0 ( driver \"echo\" )\n"
    "sonar:0 ( driver \"source\" )\n"
    "ir:0 ( driver \"slowreply\" )\n";

constexpr protocol::DeviceAddress kPosition{protocol::kPositionCode, 0};
constexpr protocol::DeviceAddress kLaser{protocol::kLaserCode, 0};
constexpr protocol::DeviceAddress kSonar{protocol::kSonarCode, 0};
constexpr protocol::DeviceAddress kIr{protocol::kIrCode, 0};

struct RequestsTest : ::testing::Test {
  TestServer server{kConfig};
  RawClient client{server.port()};
  void SetUp() override { client.read_banner(); }
};

TEST_F(RequestsTest, RequestToAnUnopenedDeviceGetsErr) {
  const auto reply = client.request(kLaser, Bytes{1, 2, 3});
  EXPECT_EQ(reply.type(), MessageType::kError);
  EXPECT_EQ(reply.device(), kLaser);
  EXPECT_TRUE(reply.payload.empty());
  // ... and after closing it again.
  client.open(kLaser, 'r');
  client.open(kLaser, 'c');
  EXPECT_EQ(client.request(kLaser, Bytes{1}).type(), MessageType::kError);
}

TEST_F(RequestsTest, DriverAnswersComeBackToTheRequester) {
  ASSERT_EQ(client.open(kLaser, 'r'), 'r');
  auto reply = client.request(kLaser, Bytes{1, 7, 7});
  EXPECT_EQ(reply.type(), MessageType::kAck);
  EXPECT_EQ(reply.device(), kLaser);
  EXPECT_EQ(reply.payload, (Bytes{1, 7, 7}));
  reply = client.request(kLaser, Bytes{9});  // the echo driver does not know 9
  EXPECT_EQ(reply.type(), MessageType::kNack);
}

TEST_F(RequestsTest, DriverWithoutRequestSupportAnswersNackPromptly) {
  ASSERT_EQ(client.open(kSonar, 'r'), 'r');
  const auto start = std::chrono::steady_clock::now();
  const auto reply = client.request(kSonar, Bytes{1});
  EXPECT_EQ(reply.type(), MessageType::kNack);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::milliseconds(500));
}

TEST_F(RequestsTest, FullRequestQueueGetsErrAndTheQueuedOneStillItsReply) {
  ASSERT_EQ(client.open(kIr, 'a'), 'a');
  client.send_request(kIr, Bytes{1, 1});
  client.send_request(kIr, Bytes{1, 2});  // queue of one, driver busy for 200 ms
  std::vector<protocol::Message> replies;
  while (replies.size() < 2) {
    auto message = client.read_message();
    if (protocol::is_reply(message.type())) replies.push_back(message);
  }
  EXPECT_EQ(replies[0].type(), MessageType::kError);
  EXPECT_EQ(replies[1].type(), MessageType::kAck);
  EXPECT_EQ(replies[1].payload, (Bytes{1, 1}));
}

TEST_F(RequestsTest, EmptyAndOverlongRequestsAreNacked) {
  ASSERT_EQ(client.open(kLaser, 'r'), 'r');
  EXPECT_EQ(client.request(kLaser, Bytes{}).type(), MessageType::kNack);
  EXPECT_EQ(client.request(kLaser, Bytes(protocol::kMaxRequestReplySize + 1, 1)).type(),
            MessageType::kNack);
  EXPECT_EQ(client.player_request(Bytes{}).type(), MessageType::kNack);
}

TEST_F(RequestsTest, RepliesGoOnlyToTheirOwnClient) {
  RawClient other(server.port());
  other.read_banner();
  ASSERT_EQ(client.open(kLaser, 'r'), 'r');
  ASSERT_EQ(other.open(kLaser, 'r'), 'r');
  client.send_request(kLaser, Bytes{1, 42});
  other.send_request(kLaser, Bytes{1, 43});
  EXPECT_EQ(client.request(kLaser, Bytes{1, 44}).payload, (Bytes{1, 42}));
  EXPECT_EQ(other.request(kLaser, Bytes{1, 45}).payload, (Bytes{1, 43}));
}

TEST_F(RequestsTest, CommandsNeedWriteAccessAndTheRightSize) {
  protocol::PositionCommand command;
  command.xspeed = 300;
  const auto bytes = protocol::encode(command);
  core::Device& position = server.device("position:0");

  ASSERT_EQ(client.open(kPosition, 'r'), 'r');
  client.send(MessageType::kCommand, kPosition, bytes);
  EXPECT_TRUE(eventually([&] { return server.logged("no write access"); }));
  EXPECT_FALSE(position.latest_command());

  ASSERT_EQ(client.open(kPosition, 'w'), 'w');
  client.send(MessageType::kCommand, kPosition, Bytes(bytes.begin(), bytes.end() - 1));
  EXPECT_TRUE(eventually([&] { return server.logged("wrong size"); }));
  client.send(MessageType::kCommand, kPosition, bytes);
  ASSERT_TRUE(eventually([&] { return position.latest_command().has_value(); }));
  EXPECT_EQ(position.latest_command()->payload, bytes);
  // No reply of any kind to a command: the next reply is the one asked for.
  EXPECT_EQ(client.player_request(Bytes{0, 1}).payload.size(), 388u);
}

TEST_F(RequestsTest, ReadOnlyDriverIgnoresCommandsEvenWithWriteAccess) {
  ASSERT_EQ(client.open(kSonar, 'a'), 'a');  // granted, as 1.5 did
  client.send(MessageType::kCommand, kSonar, Bytes{1, 2});
  EXPECT_TRUE(eventually([&] { return server.logged("takes no commands"); }));
}

TEST_F(RequestsTest, LastClientLeavingStopsThePositionDevice) {
  core::Device& position = server.device("position:0");
  {
    RawClient driver_client(server.port());
    driver_client.read_banner();
    ASSERT_EQ(driver_client.open(kPosition, 'a'), 'a');
    protocol::PositionCommand go;
    go.xspeed = 500;
    go.yawspeed = 20;
    driver_client.send(MessageType::kCommand, kPosition, protocol::encode(go));
    ASSERT_TRUE(eventually([&] { return position.latest_command().has_value(); }));
  }
  ASSERT_TRUE(eventually([&] { return position.subscriptions() == 0; }));
  const auto stop = protocol::decode<protocol::PositionCommand>(position.latest_command()->payload);
  EXPECT_EQ(stop.xspeed, 0);
  EXPECT_EQ(stop.yspeed, 0);
  EXPECT_EQ(stop.yawspeed, 0);
}

TEST_F(RequestsTest, ClientsGoingAwayReleaseTheirSubscriptions) {
  {
    RawClient a(server.port());
    a.read_banner();
    ASSERT_EQ(a.open(kSonar, 'a'), 'a');
    ASSERT_EQ(client.open(kSonar, 'r'), 'r');
    EXPECT_EQ(server.device("sonar:0").subscriptions(), 3);
  }
  EXPECT_TRUE(eventually([&] { return server.device("sonar:0").subscriptions() == 1; }));
  server.stop();
  EXPECT_EQ(server.device("sonar:0").subscriptions(), 0);
}

}  // namespace requests_test
}  // namespace playerkit::testing
