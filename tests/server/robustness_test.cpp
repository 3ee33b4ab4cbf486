// Bad input, authentication, many clients and slow clients: the server keeps
// serving everyone else.

#include <gtest/gtest.h>

#include <thread>

#include "protocol/interfaces.hpp"
#include "support/raw_client.hpp"
#include "test_server.hpp"

namespace playerkit::testing {
namespace robustness_test {

using protocol::MessageType;
using Bytes = std::vector<std::uint8_t>;
using Clock = std::chrono::steady_clock;

constexpr protocol::DeviceAddress kPlayer{protocol::kPlayerCode, 0};
constexpr protocol::DeviceAddress kLaser{protocol::kLaserCode, 0};

Bytes auth_payload(std::string_view key) {
  Bytes payload(34, 0);  // subtype 7, then the key NUL-padded to 32 bytes
  payload[1] = 7;
  std::copy(key.begin(), key.end(), payload.begin() + 2);
  return payload;
}

TEST(RobustnessTest, GarbageBeforeAMessageIsSkipped) {
  TestServer server("laser:0 ( driver \"echo\" )\n");
  RawClient client(server.port());
  client.read_banner();
  client.send_bytes(Bytes{'n', 'o', 'i', 's', 'e', 0x58, 0x00, 0x78});
  const auto reply = client.player_request(Bytes{0, 1});
  EXPECT_EQ(reply.type(), MessageType::kAck);
  EXPECT_EQ(reply.payload.size(), 388u);
  EXPECT_TRUE(server.logged("skipped 8 bytes"));
}

TEST(RobustnessTest, OversizeRequestIsAnsweredAndTheConnectionSurvives) {
  TestServer server("laser:0 ( driver \"echo\" )\n");
  RawClient client(server.port());
  client.read_banner();
  ASSERT_EQ(client.open(kLaser, 'r'), 'r');
  Bytes huge(protocol::kMaxPayloadSize + 100, 0x58);  // full of marker bytes
  const auto reply = client.request(kLaser, huge);
  EXPECT_EQ(reply.type(), MessageType::kNack);
  EXPECT_EQ(reply.device(), kLaser);
  EXPECT_TRUE(server.logged("dropped a message of 8260 bytes"));
  EXPECT_EQ(client.request(kLaser, Bytes{1, 5}).payload, (Bytes{1, 5}));
}

TEST(RobustnessTest, OversizeCommandIsDroppedWithoutReply) {
  TestServer server("position:0 ( driver \"actuator\" )\n");
  RawClient client(server.port());
  client.read_banner();
  ASSERT_EQ(client.open({protocol::kPositionCode, 0}, 'w'), 'w');
  client.send(MessageType::kCommand, {protocol::kPositionCode, 0}, Bytes(9000, 1));
  EXPECT_EQ(client.player_request(Bytes{0, 1}).type(), MessageType::kAck);
  EXPECT_FALSE(server.device("position:0").latest_command());
}

TEST(RobustnessTest, MessagesOfOtherTypesAreIgnored) {
  TestServer server("laser:0 ( driver \"echo\" )\n");
  RawClient client(server.port());
  client.read_banner();
  client.send(MessageType::kData, kPlayer, Bytes{1, 2});
  client.send(MessageType::kSynch, kPlayer, Bytes{});
  client.send(static_cast<MessageType>(99), kPlayer, Bytes{1});
  // The next reply is the DEVLIST's: nothing answered the others.
  EXPECT_EQ(client.player_request(Bytes{0, 1}).payload.size(), 388u);
  EXPECT_TRUE(server.logged("type 99"));
}

TEST(RobustnessTest, AuthenticationGatesEverythingButTheBanner) {
  server::ServerOptions options;
  options.auth_key = "sesame";
  TestServer server("laser:0 ( driver \"source\" )\n", options);

  RawClient waiting(server.port());
  EXPECT_EQ(waiting.read_banner().size(), 32u);
  EXPECT_FALSE(waiting.read_message(std::chrono::milliseconds(300)));  // no SYNCH rounds

  RawClient wrong(server.port());
  wrong.read_banner();
  wrong.send_request(kPlayer, auth_payload("open up"));
  EXPECT_TRUE(wrong.wait_for_close(std::chrono::seconds(2)));

  RawClient impatient(server.port());
  impatient.read_banner();
  impatient.send_request(kPlayer, Bytes{0, 1});  // DEVLIST before AUTH
  EXPECT_TRUE(impatient.wait_for_close(std::chrono::seconds(2)));

  RawClient oversize(server.port());
  oversize.read_banner();
  oversize.send_request(kPlayer, Bytes(protocol::kMaxPayloadSize + 1, 0));
  EXPECT_TRUE(oversize.wait_for_close(std::chrono::seconds(2)));

  RawClient right(server.port());
  right.read_banner();
  right.send_request({protocol::kPlayerCode, 3}, auth_payload("sesame"));
  const auto ack = right.read_message();
  EXPECT_EQ(ack.type(), MessageType::kAck);
  EXPECT_EQ(ack.header.device_index, 3);
  EXPECT_TRUE(ack.payload.empty());
  EXPECT_EQ(right.read_message().type(), MessageType::kSynch);
  EXPECT_EQ(right.open(kLaser, 'r'), 'r');
  // A second AUTH once authenticated is just refused.
  EXPECT_EQ(right.player_request(auth_payload("sesame")).type(), MessageType::kNack);
}

TEST(RobustnessTest, AuthenticationKeyIsComparedOn31Characters) {
  server::ServerOptions options;
  options.auth_key = std::string(31, 'k') + "IGNORED";
  TestServer server("laser:0 ( driver \"source\" )\n", options);
  RawClient client(server.port());
  client.read_banner();
  client.send_request(kPlayer, auth_payload(std::string(31, 'k')));
  EXPECT_EQ(client.read_message().type(), MessageType::kAck);
}

TEST(RobustnessTest, FiftyConcurrentClientsAllGetTheirData) {
  TestServer server("laser:0 ( driver \"source\" )\nsonar:0 ( driver \"source\" )\n");
  std::vector<RawClient> clients;
  for (int i = 0; i < 50; ++i) {
    clients.emplace_back(server.port());
    clients.back().read_banner();
  }
  for (auto& client : clients) {
    ASSERT_EQ(client.open(kLaser, 'r'), 'r');
    ASSERT_EQ(client.open({protocol::kSonarCode, 0}, 'r'), 'r');
  }
  EXPECT_EQ(server.server().client_count(), 50u);
  EXPECT_EQ(server.device("laser:0").subscriptions(), 50);
  server.device("laser:0").publish({4, 2}, {7, 0});
  server.device("sonar:0").publish({9}, {7, 0});
  for (auto& client : clients) {
    std::vector<protocol::Message> data;
    while (data.size() < 2) {
      for (auto& message : client.read_round()) {
        if (message.type() == MessageType::kData) data.push_back(message);
      }
    }
    EXPECT_EQ(data[0].payload, (Bytes{4, 2}));
    EXPECT_EQ(data[1].payload, (Bytes{9}));
  }
  clients.clear();
  EXPECT_TRUE(eventually([&] { return server.server().client_count() == 0; }));
  EXPECT_EQ(server.device("laser:0").subscriptions(), 0);
}

TEST(RobustnessTest, AClientThatReadsLateGetsEveryReplyInOrder) {
  TestServer server("laser:0 ( driver \"echo\" )\n");
  RawClient client(server.port(), {.receive_buffer_bytes = 4096});
  client.read_banner();
  ASSERT_EQ(client.open(kLaser, 'r'), 'r');
  // 1800 replies of 2 KB (3.6 MB) are more than both sockets' buffers hold: the
  // server's writes stop taking bytes and it must wait for room, then go on.
  constexpr int kRequests = 1800;
  for (int i = 0; i < kRequests; ++i) {
    Bytes payload(2000, 0x55);
    payload[0] = 1;  // the echo driver's subtype
    payload[1] = static_cast<std::uint8_t>(i >> 8);
    payload[2] = static_cast<std::uint8_t>(i & 0xff);
    client.send_request(kLaser, payload);
  }
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  int next = 0;
  while (next < kRequests) {
    const auto message = client.read_message(std::chrono::seconds(10));
    ASSERT_TRUE(message) << "reply " << next << " never came";
    if (message->type() == MessageType::kSynch) continue;
    ASSERT_EQ(message->type(), MessageType::kAck);
    ASSERT_EQ(message->payload.size(), 2000u);
    ASSERT_EQ(message->payload[1] << 8 | message->payload[2], next) << "replies out of order";
    ++next;
  }
  EXPECT_FALSE(server.logged("does not read its replies"));
  EXPECT_FALSE(server.logged("has not read anything"));
}

TEST(RobustnessTest, AStalledClientDoesNotDelayOthersAndIsDisconnected) {
  server::ServerOptions options;
  options.stall_timeout = std::chrono::milliseconds(1500);
  TestServer server("laser:0 ( driver \"source\" )\n", options);
  // Big samples at a high rate fill a small socket buffer within milliseconds.
  server.device("laser:0").publish(Bytes(8000, 1), {1, 0});

  RawClient stalled(server.port(), {.receive_buffer_bytes = 4096});
  stalled.read_banner();
  ASSERT_EQ(stalled.open(kLaser, 'r'), 'r');
  ASSERT_EQ(stalled.set_data_mode(protocol::DataMode::kPushAll), MessageType::kAck);
  ASSERT_EQ(stalled.set_frequency(500), MessageType::kAck);
  // ... and from here on it reads nothing.

  RawClient healthy(server.port());
  healthy.read_banner();
  ASSERT_EQ(healthy.open(kLaser, 'r'), 'r');
  std::uint32_t stamp = 2;
  std::vector<double> delays_ms;
  const auto until = Clock::now() + std::chrono::milliseconds(1000);
  while (Clock::now() < until) {
    server.device("laser:0").publish(Bytes(8000, 2), {stamp++, 0});
    const auto published = Clock::now();
    for (;;) {
      auto round = healthy.read_round();
      if (round.size() > 1) break;
    }
    delays_ms.push_back(std::chrono::duration<double, std::milli>(Clock::now() - published).count());
  }
  ASSERT_GE(delays_ms.size(), 5u);
  // At 10 Hz a sample waits about one period (100 ms) for its round. A server
  // that let the stalled client's full socket hold up the loop would delay it
  // until the stall timeout cut that client off (1500 ms); half of that
  // separates the two without depending on how loaded the test machine is.
  const double stall_ms = std::chrono::duration<double, std::milli>(options.stall_timeout).count();
  EXPECT_LT(*std::max_element(delays_ms.begin(), delays_ms.end()), stall_ms / 2);

  EXPECT_TRUE(eventually([&] { return server.logged("has not read anything"); }, std::chrono::seconds(5)));
  EXPECT_TRUE(stalled.wait_for_close(std::chrono::seconds(2)));
  EXPECT_TRUE(eventually([&] { return server.device("laser:0").subscriptions() == 1; }));
  for (int i = 0; i < 3; ++i) EXPECT_EQ(healthy.read_round().back().type(), MessageType::kSynch);
}

}  // namespace robustness_test
}  // namespace playerkit::testing
