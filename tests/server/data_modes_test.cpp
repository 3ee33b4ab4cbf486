// The four data modes, end to end (server-behaviour.md §4).

#include <gtest/gtest.h>

#include "protocol/interfaces.hpp"
#include "support/raw_client.hpp"
#include "test_server.hpp"

namespace playerkit::testing {
namespace data_modes_test {

using protocol::DataMode;
using protocol::MessageType;
using Bytes = std::vector<std::uint8_t>;

constexpr const char* kConfig =
    "laser:0 ( driver \"source\" )\n"
    "sonar:0 ( driver \"source\" )\n";

struct DataModesTest : ::testing::Test {
  TestServer server{kConfig};
  RawClient client{server.port()};

  void SetUp() override {
    client.read_banner();
    ASSERT_EQ(client.open({protocol::kLaserCode, 0}, 'r'), 'r');
    ASSERT_EQ(client.open({protocol::kSonarCode, 0}, 'r'), 'r');
  }
  // Reads rounds until one carries data (bounded by the client's timeout).
  std::vector<protocol::Message> next_round_with_data() {
    for (int i = 0; i < 50; ++i) {
      auto round = client.read_round();
      if (round.size() > 1) return round;
    }
    return {};
  }
  // Data messages in the rounds that arrive within `duration`.
  std::size_t data_messages_within(std::chrono::milliseconds duration) {
    std::size_t count = 0;
    const auto deadline = std::chrono::steady_clock::now() + duration;
    while (std::chrono::steady_clock::now() < deadline) {
      auto message = client.read_message(std::chrono::milliseconds(20));
      if (message && message->type() == MessageType::kData) ++count;
    }
    return count;
  }
  // Sends a request and keeps every message up to and including its reply.
  std::vector<protocol::Message> request_and_collect(Bytes payload) {
    client.send_request({protocol::kPlayerCode, 0}, payload);
    std::vector<protocol::Message> seen;
    do {
      seen.push_back(client.read_message());
    } while (!protocol::is_reply(seen.back().type()));
    return seen;
  }
};

TEST_F(DataModesTest, PushNewSendsEachSampleOnceInSubscriptionOrder) {
  server.device("sonar:0").publish({2}, {5, 0});
  server.device("laser:0").publish({1}, {5, 1});
  const auto round = next_round_with_data();
  ASSERT_EQ(round.size(), 3u);
  EXPECT_EQ(round[0].device().interface, protocol::kLaserCode);  // opened first
  EXPECT_EQ(round[0].type(), MessageType::kData);
  EXPECT_EQ(round[0].timestamp(), (protocol::Timestamp{5, 1}));
  EXPECT_EQ(round[1].device().interface, protocol::kSonarCode);
  EXPECT_EQ(round[2].type(), MessageType::kSynch);
  EXPECT_EQ(data_messages_within(std::chrono::milliseconds(350)), 0u);
  server.device("laser:0").publish({3}, {6, 0});
  const auto later = next_round_with_data();
  ASSERT_EQ(later.size(), 2u);
  EXPECT_EQ(later[0].payload, (Bytes{3}));
}

TEST_F(DataModesTest, PushAllRepeatsTheLatestSampleEveryRound) {
  ASSERT_EQ(client.set_data_mode(DataMode::kPushAll), MessageType::kAck);
  server.device("laser:0").publish({1}, {5, 0});
  ASSERT_EQ(client.set_frequency(50), MessageType::kAck);
  // ~15 rounds in 300 ms at 50 Hz, each with the laser's (unchanged) sample.
  EXPECT_GE(data_messages_within(std::chrono::milliseconds(300)), 8u);
}

TEST_F(DataModesTest, PullNewSendsOneRoundPerDataRequestWithOnlyNewData) {
  ASSERT_EQ(client.set_data_mode(DataMode::kPullNew), MessageType::kAck);
  while (client.read_message(std::chrono::milliseconds(150))) {
  }  // a push round may have been on its way
  server.device("laser:0").publish({1}, {5, 0});
  EXPECT_FALSE(client.read_message(std::chrono::milliseconds(300)));  // nothing unasked

  auto seen = request_and_collect({0, 4});
  EXPECT_EQ(seen.back().type(), MessageType::kAck);
  auto round = client.read_round();
  ASSERT_EQ(round.size(), 2u);
  EXPECT_EQ(round[0].payload, (Bytes{1}));
  EXPECT_FALSE(client.read_message(std::chrono::milliseconds(200)));

  request_and_collect({0, 4});
  round = client.read_round();
  EXPECT_EQ(round.size(), 1u);  // nothing new: just the SYNCH
}

TEST_F(DataModesTest, PullAllResendsOnEveryRequest) {
  ASSERT_EQ(client.set_data_mode(DataMode::kPullAll), MessageType::kAck);
  server.device("laser:0").publish({1}, {5, 0});
  for (int i = 0; i < 3; ++i) {
    request_and_collect({0, 4});
    const auto round = client.read_round();
    ASSERT_EQ(round.size(), 2u) << "request " << i;
    EXPECT_EQ(round[0].payload, (Bytes{1}));
  }
}

TEST_F(DataModesTest, DataRequestInPushModeIsRefused) {
  const auto seen = request_and_collect({0, 4});
  EXPECT_EQ(seen.back().type(), MessageType::kNack);
}

TEST_F(DataModesTest, WriteOnlySubscriptionStillGetsSynchs) {
  RawClient writer(server.port());
  writer.read_banner();
  ASSERT_EQ(writer.open({protocol::kLaserCode, 0}, 'w'), 'w');
  server.device("laser:0").publish({1}, {5, 0});
  for (int i = 0; i < 3; ++i) {
    const auto round = writer.read_round();
    EXPECT_EQ(round.size(), 1u);  // no data for 'w', but the SYNCH keeps coming
  }
}

}  // namespace data_modes_test
}  // namespace playerkit::testing
