// The first things a 1.5 client sees: the banner, SYNCH rounds at its
// frequency, and the `player` device's answers.

#include <gtest/gtest.h>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/player.hpp"
#include "support/raw_client.hpp"
#include "test_server.hpp"

namespace playerkit::testing {
namespace handshake_test {

using protocol::MessageType;
using Bytes = std::vector<std::uint8_t>;
using Clock = std::chrono::steady_clock;

constexpr const char* kConfig =
    "position:0 ( driver \"actuator\" )\n"
    "laser:0 ( driver \"source\" )\n";

// Mean interval between `count` consecutive SYNCH messages, in milliseconds.
double mean_synch_interval_ms(RawClient& client, int count) {
  std::vector<Clock::time_point> arrivals;
  while (static_cast<int>(arrivals.size()) < count + 1) {
    const auto message = client.read_message();
    if (message.type() == MessageType::kSynch) arrivals.push_back(Clock::now());
  }
  return std::chrono::duration<double, std::milli>(arrivals.back() - arrivals.front()).count() / count;
}

TEST(HandshakeTest, BannerIsTheFirst32Bytes) {
  TestServer server(kConfig);
  RawClient client(server.port());
  Bytes expected(32, 0);
  const std::string text = "Player v.1.5";
  std::copy(text.begin(), text.end(), expected.begin());
  EXPECT_EQ(client.read_banner(), expected);
  // What follows is a message header, not more banner.
  const auto first = client.read_message();
  EXPECT_EQ(first.header.stx, protocol::kStx);
}

TEST(HandshakeTest, ANewClientGetsSynchOnlyRoundsAt10Hz) {
  TestServer server(kConfig);
  RawClient client(server.port());
  client.read_banner();
  const auto synch = client.read_message();
  EXPECT_EQ(synch.type(), MessageType::kSynch);
  EXPECT_EQ(synch.header.device, protocol::kPlayerCode);
  EXPECT_EQ(synch.header.device_index, 0);
  EXPECT_EQ(synch.header.size, 0u);
  EXPECT_EQ(synch.time(), synch.timestamp());
  const double interval = mean_synch_interval_ms(client, 8);
  EXPECT_NEAR(interval, 100.0, 15.0);
}

TEST(HandshakeTest, DataFrequencyChangesTheRoundRateAndZeroStopsIt) {
  TestServer server(kConfig);
  RawClient client(server.port());
  client.read_banner();
  EXPECT_EQ(client.set_frequency(50), MessageType::kAck);
  EXPECT_NEAR(mean_synch_interval_ms(client, 25), 20.0, 5.0);
  EXPECT_EQ(client.set_frequency(0), MessageType::kAck);
  // Drain a round that may have been on its way, then expect silence.
  while (client.read_message(std::chrono::milliseconds(50))) {
  }
  EXPECT_FALSE(client.read_message(std::chrono::milliseconds(300)));
}

TEST(HandshakeTest, PlayerRepliesEchoDeviceAndIndexAndStampNow) {
  TestServer server(kConfig);
  RawClient client(server.port());
  client.read_banner();
  client.send_request({protocol::kPlayerCode, 5}, Bytes{0, 1});
  protocol::Message reply;
  do {
    reply = client.read_message();
  } while (!protocol::is_reply(reply.type()));
  EXPECT_EQ(reply.type(), MessageType::kAck);
  EXPECT_EQ(reply.header.device, protocol::kPlayerCode);
  EXPECT_EQ(reply.header.device_index, 5);
  EXPECT_EQ(reply.header.reserved, 0u);
  EXPECT_EQ(reply.time(), reply.timestamp());
  const auto wall = core::WallClock().now();
  EXPECT_LE(reply.time().sec, wall.sec);
  EXPECT_GE(reply.time().sec + 2, wall.sec);
}

TEST(HandshakeTest, DeviceListDriverInfoAndOpening) {
  TestServer server(kConfig);
  RawClient client(server.port());
  client.read_banner();

  const auto list_reply = client.player_request(Bytes{0, 1});
  ASSERT_EQ(list_reply.payload.size(), 388u);
  const auto list = protocol::decode<protocol::DeviceList>(list_reply.payload);
  ASSERT_EQ(list.device_count, 2);
  EXPECT_EQ(list.devices[0], (protocol::DeviceId{protocol::kPositionCode, 0, server.port()}));
  EXPECT_EQ(list.devices[1], (protocol::DeviceId{protocol::kLaserCode, 0, server.port()}));

  protocol::DriverInfo info;
  info.subtype = protocol::kPlayerDriverinfoReq;
  info.id = {protocol::kLaserCode, 0, server.port()};
  const auto info_reply = client.player_request(protocol::encode(info));
  EXPECT_EQ(protocol::decode<protocol::DriverInfo>(info_reply.payload).driver_name.view(), "source");

  EXPECT_EQ(client.open({protocol::kLaserCode, 0}, 'r'), 'r');
  EXPECT_EQ(server.device("laser:0").subscriptions(), 1);
  EXPECT_EQ(client.open({protocol::kLaserCode, 3}, 'r'), 'e');  // not declared
  EXPECT_EQ(client.open({protocol::kPositionCode, 0}, 'a'), 'a');
  EXPECT_EQ(server.device("position:0").subscriptions(), 2);
  EXPECT_EQ(client.open({protocol::kPositionCode, 0}, 'c'), 'c');
  EXPECT_EQ(server.device("position:0").subscriptions(), 0);
}

TEST(HandshakeTest, RefusedSetupGrantsEWithTheDriverName) {
  TestServer server("sonar:0 ( driver \"refuser\" )\n");
  RawClient client(server.port());
  client.read_banner();
  const auto reply = client.player_request(Bytes{0, 3, 0, 5, 0, 0, 'r'});
  EXPECT_EQ(reply.type(), MessageType::kAck);
  const auto access = protocol::decode<protocol::DeviceAccessReply>(reply.payload);
  EXPECT_EQ(access.access, 'e');
  EXPECT_EQ(access.driver_name.view(), "refuser");
  EXPECT_TRUE(server.logged("the test says no"));
}

TEST(HandshakeTest, EachPortServesItsOwnDevicesAndNameServiceFindsRobots) {
  TestServer server(
      "laser:0 ( driver \"source\" )\n"
      "robot:{PORT2}:bob ( )\n"
      "sonar:0 ( driver \"source\" )\n"
      "sonar:1 ( driver \"source\" )\n",
      {}, /*extra_ports=*/1);
  RawClient first(server.port(0));
  RawClient second(server.port(1));
  first.read_banner();
  second.read_banner();
  auto list = protocol::decode<protocol::DeviceList>(first.player_request(Bytes{0, 1}).payload);
  EXPECT_EQ(list.device_count, 1);
  list = protocol::decode<protocol::DeviceList>(second.player_request(Bytes{0, 1}).payload);
  ASSERT_EQ(list.device_count, 2);
  EXPECT_EQ(list.devices[1], (protocol::DeviceId{protocol::kSonarCode, 1, server.port(1)}));
  EXPECT_EQ(first.open({protocol::kSonarCode, 0}, 'r'), 'e');  // lives on the other port
  EXPECT_EQ(second.open({protocol::kSonarCode, 0}, 'r'), 'r');

  protocol::NameServiceRequest lookup;
  lookup.subtype = protocol::kPlayerNameserviceReq;
  lookup.name = "bob";
  const auto answer = protocol::decode<protocol::NameServiceRequest>(
      first.player_request(protocol::encode(lookup)).payload);
  EXPECT_EQ(answer.port, server.port(1));
}

TEST(HandshakeTest, TwoServersOnDifferentPortsAreIndependent) {
  TestServer one("laser:0 ( driver \"source\" )\n");
  TestServer two("sonar:0 ( driver \"source\" )\n");
  ASSERT_NE(one.port(), two.port());
  RawClient a(one.port());
  RawClient b(two.port());
  a.read_banner();
  b.read_banner();
  EXPECT_EQ(a.open({protocol::kLaserCode, 0}, 'r'), 'r');
  EXPECT_EQ(b.open({protocol::kLaserCode, 0}, 'r'), 'e');
  EXPECT_EQ(b.open({protocol::kSonarCode, 0}, 'r'), 'r');
  one.device("laser:0").publish({1, 2}, {1, 0});
  two.device("sonar:0").publish({3}, {1, 0});
  auto round = a.read_round();
  while (round.size() < 2) round = a.read_round();
  EXPECT_EQ(round[0].payload, (Bytes{1, 2}));
  round = b.read_round();
  while (round.size() < 2) round = b.read_round();
  EXPECT_EQ(round[0].payload, (Bytes{3}));
}

}  // namespace handshake_test
}  // namespace playerkit::testing
