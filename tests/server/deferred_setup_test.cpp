// Devices whose setup may block (core::Driver::setup_may_block()) are set up
// off the server's event loop: the client opening one gets its DEV reply when
// the setup ends, in its place among that client's replies, and every other
// client is served meanwhile.

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <memory>
#include <stdexcept>
#include <thread>
#include <vector>

#include "protocol/interfaces.hpp"
#include "protocol/message.hpp"
#include "support/eventually.hpp"
#include "support/raw_client.hpp"
#include "test_server.hpp"

namespace playerkit::testing {
namespace deferred_setup_test {

using namespace std::chrono_literals;
using protocol::DeviceAddress;
using protocol::MessageType;
using Bytes = std::vector<std::uint8_t>;

constexpr auto kSetupTime = 1000ms;

struct SetupCalls {
  std::atomic<int> setups{0};
  std::atomic<int> shutdowns{0};
};

// Takes kSetupTime to set up, as a remote or a handshake might; "slowfail"
// then refuses.
class SlowSetupDriver : public core::Driver {
 public:
  SlowSetupDriver(SetupCalls& calls, bool fails) : calls_(calls), fails_(fails) {}
  void setup() override {
    ++calls_.setups;
    std::this_thread::sleep_for(kSetupTime);
    if (fails_) throw core::DriverError("nothing answered");
  }
  void shutdown() override { ++calls_.shutdowns; }
  [[nodiscard]] bool setup_may_block() const override { return true; }

 private:
  SetupCalls& calls_;
  bool fails_;
};

constexpr const char* kConfig =
    "laser:0 ( driver \"source\" )\n"
    "laser:1 ( driver \"slowsetup\" )\n"
    "laser:2 ( driver \"slowfail\" )\n";

constexpr DeviceAddress kFast{protocol::kLaserCode, 0};
constexpr DeviceAddress kSlow{protocol::kLaserCode, 1};
constexpr DeviceAddress kFailing{protocol::kLaserCode, 2};

Bytes dev_request(DeviceAddress device, char access) {
  Bytes payload = u16_bytes(protocol::kPlayerDevReq);
  for (const auto& part : {u16_bytes(device.interface), u16_bytes(device.index)}) {
    payload.insert(payload.end(), part.begin(), part.end());
  }
  payload.push_back(static_cast<std::uint8_t>(access));
  return payload;
}

// The next `count` replies, skipping data and SYNCH.
std::vector<protocol::Message> read_replies(RawClient& client, std::size_t count) {
  std::vector<protocol::Message> replies;
  for (int messages = 0; replies.size() < count && messages < 10000; ++messages) {
    auto message = client.read_message();
    if (protocol::is_reply(message.type())) replies.push_back(std::move(message));
  }
  return replies;
}

std::uint16_t subtype_of(const protocol::Message& reply) {
  return reply.payload.size() < 2 ? 0 : static_cast<std::uint16_t>((reply.payload[0] << 8) | reply.payload[1]);
}

struct DeferredSetupTest : ::testing::Test {
  SetupCalls calls;
  TestServer server{kConfig, {}, 0, [this](core::DriverRegistry& registry) {
                      const auto every = [] {
                        std::vector<std::uint16_t> codes;
                        for (const auto& info : protocol::all_interfaces()) codes.push_back(info.code);
                        return codes;
                      }();
                      registry.add({"slowsetup", every, protocol::Access::kAll,
                                    [this](const core::DriverContext&) {
                                      return std::make_unique<SlowSetupDriver>(calls, false);
                                    },
                                    {}, ""});
                      registry.add({"slowfail", every, protocol::Access::kAll,
                                    [this](const core::DriverContext&) {
                                      return std::make_unique<SlowSetupDriver>(calls, true);
                                    },
                                    {}, ""});
                    }};
};

TEST_F(DeferredSetupTest, DevReplyKeepsItsPlaceAmongTheClientsReplies) {
  RawClient client(server.port());
  client.read_banner();
  const auto start = std::chrono::steady_clock::now();
  // Three requests at once: the DEV waits for the setup, the others behind it.
  client.send_request({protocol::kPlayerCode, 0}, dev_request(kSlow, 'r'));
  client.send_request({protocol::kPlayerCode, 0}, u16_bytes(protocol::kPlayerDevlistReq));
  client.send_request({protocol::kPlayerCode, 0}, dev_request(kFast, 'r'));
  const auto replies = read_replies(client, 3);
  ASSERT_EQ(replies.size(), 3u);
  EXPECT_GE(std::chrono::steady_clock::now() - start, kSetupTime);
  EXPECT_EQ(subtype_of(replies[0]), protocol::kPlayerDevReq);
  ASSERT_EQ(replies[0].payload.size(), 71u);
  EXPECT_EQ(replies[0].payload[6], 'r');
  EXPECT_EQ(subtype_of(replies[1]), protocol::kPlayerDevlistReq);
  EXPECT_EQ(subtype_of(replies[2]), protocol::kPlayerDevReq);
  EXPECT_EQ(replies[2].payload[6], 'r');
  EXPECT_EQ(calls.setups, 1);
  EXPECT_EQ(server.device("laser:1").subscriptions(), 1);  // the client's; the setup's is given back
  // Closing it shuts the driver down.
  EXPECT_EQ(client.open(kSlow, 'c'), 'c');
  EXPECT_TRUE(eventually([&] { return calls.shutdowns.load() == 1; }));
}

TEST_F(DeferredSetupTest, OtherClientsAreAnsweredWhileADeviceSetsUp) {
  RawClient slow_opener(server.port());
  slow_opener.read_banner();
  RawClient other(server.port());
  other.read_banner();
  slow_opener.send_request({protocol::kPlayerCode, 0}, dev_request(kSlow, 'r'));
  ASSERT_TRUE(eventually([&] { return calls.setups.load() == 1; }));
  // Answered while the setup is still under way (it takes kSetupTime).
  EXPECT_EQ(other.open(kFast, 'r'), 'r');
  EXPECT_EQ(server.device("laser:1").subscriptions(), 0);
  const auto replies = read_replies(slow_opener, 1);
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0].payload[6], 'r');
}

TEST_F(DeferredSetupTest, FailedSetupGrantsErrorAndIsNotTriedTwice) {
  RawClient client(server.port());
  client.read_banner();
  EXPECT_EQ(client.open(kFailing, 'a'), 'e');
  EXPECT_EQ(calls.setups, 1);
  EXPECT_EQ(server.device("laser:2").subscriptions(), 0);
  EXPECT_EQ(calls.shutdowns, 0);
  EXPECT_TRUE(server.logged("nothing answered"));
}

TEST_F(DeferredSetupTest, ClientsOpeningTogetherShareOneSetup) {
  RawClient first(server.port());
  first.read_banner();
  RawClient second(server.port());
  second.read_banner();
  first.send_request({protocol::kPlayerCode, 0}, dev_request(kSlow, 'a'));
  second.send_request({protocol::kPlayerCode, 0}, dev_request(kSlow, 'r'));
  const auto first_reply = read_replies(first, 1);
  const auto second_reply = read_replies(second, 1);
  ASSERT_EQ(first_reply.size(), 1u);
  ASSERT_EQ(second_reply.size(), 1u);
  EXPECT_EQ(first_reply[0].payload[6], 'a');
  EXPECT_EQ(second_reply[0].payload[6], 'r');
  EXPECT_EQ(calls.setups, 1);
  EXPECT_EQ(server.device("laser:1").subscriptions(), 3);
}

TEST_F(DeferredSetupTest, ClientGoneDuringTheSetupLeavesTheDeviceShutDown) {
  {
    RawClient client(server.port());
    client.read_banner();
    client.send_request({protocol::kPlayerCode, 0}, dev_request(kSlow, 'r'));
    ASSERT_TRUE(eventually([&] { return calls.setups.load() == 1; }));
  }  // disconnects while the setup runs
  EXPECT_TRUE(eventually([&] { return calls.shutdowns.load() == 1; }, 10s));
  EXPECT_EQ(server.device("laser:1").subscriptions(), 0);
}

TEST_F(DeferredSetupTest, StoppingTheServerDuringASetupGivesItsSubscriptionBack) {
  RawClient client(server.port());
  client.read_banner();
  client.send_request({protocol::kPlayerCode, 0}, dev_request(kSlow, 'r'));
  ASSERT_TRUE(eventually([&] { return calls.setups.load() == 1; }));
  server.stop();
  EXPECT_EQ(server.device("laser:1").subscriptions(), 0);
  EXPECT_EQ(calls.shutdowns, 1);
}

}  // namespace deferred_setup_test
}  // namespace playerkit::testing
