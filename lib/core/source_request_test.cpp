#include "core/source_request.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <thread>

#include "core/test_drivers.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::core {
namespace source_request_test {

using namespace std::chrono_literals;

struct SourceRequestFixture : ::testing::Test {
  void SetUp() override { logger.set_sink([](LogLevel, std::string_view) {}); }
  std::unique_ptr<Device> make(std::size_t request_queue = 8) {
    DeviceLimits limits;
    limits.request_queue = request_queue;
    DeviceInfo info{"counting", "", protocol::Access::kAll, limits, false};
    return std::make_unique<Device>(DeviceKey{6665, {protocol::kLaserCode, 0}}, info,
                                    std::make_unique<testing::CountingDriver>(counts), clock, logger);
  }
  testing::CallCounts counts;
  ManualClock clock;
  Logger logger;
};

// The server's loop, serving a loop-driven device's requests until stopped.
class ServingLoop {
 public:
  explicit ServingLoop(Device& device)
      : thread_([&device](std::stop_token stop) {
          while (!stop.stop_requested()) {
            device.service_requests();
            std::this_thread::sleep_for(1ms);
          }
        }) {}

 private:
  std::jthread thread_;
};

TEST_F(SourceRequestFixture, TheReplyComesBackToTheAskerAndNotToTheServer) {
  auto laser = make();
  ServingLoop loop(*laser);
  const auto reply = ask_source(*laser, {1, 42}, 5s);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->type, protocol::MessageType::kAck);
  EXPECT_EQ(reply->payload, (std::vector<std::uint8_t>{1, 42}));
  EXPECT_EQ(reply->device, (protocol::DeviceAddress{protocol::kLaserCode, 0}));
  EXPECT_GE(reply->client, kFirstDriverClient);
  EXPECT_TRUE(laser->take_replies().empty());
  // A refusal is an answer too.
  const auto refused = ask_source(*laser, {7}, 5s);
  ASSERT_TRUE(refused);
  EXPECT_EQ(refused->type, protocol::MessageType::kNack);
}

TEST_F(SourceRequestFixture, ClientsRepliesStillGoToTheServer) {
  auto laser = make();
  ASSERT_EQ(laser->enqueue_request({3, {protocol::kLaserCode, 0}, {1, 5}, {}}), Device::RequestStatus::kQueued);
  laser->service_requests();
  const auto replies = laser->take_replies();
  ASSERT_EQ(replies.size(), 1u);
  EXPECT_EQ(replies[0].client, 3u);
}

TEST_F(SourceRequestFixture, NoReplyInTimeIsNulloptAndTheLateReplyGoesNowhere) {
  auto laser = make();
  EXPECT_FALSE(ask_source(*laser, {1, 1}, 20ms));
  laser->service_requests();  // the source answers only now
  EXPECT_TRUE(laser->take_replies().empty());
  // The next asker gets its own reply, not the stale one.
  ServingLoop loop(*laser);
  const auto reply = ask_source(*laser, {1, 2}, 5s);
  ASSERT_TRUE(reply);
  EXPECT_EQ(reply->payload, (std::vector<std::uint8_t>{1, 2}));
}

TEST_F(SourceRequestFixture, AFullRequestQueueIsRefusedAtOnce) {
  auto laser = make(1);
  ASSERT_EQ(laser->enqueue_request({3, {protocol::kLaserCode, 0}, {1}, {}}), Device::RequestStatus::kQueued);
  // An hour's timeout: waiting for a reply instead of refusing would hang the test.
  EXPECT_FALSE(ask_source(*laser, {1, 1}, std::chrono::hours(1)));
  EXPECT_EQ(laser->pending_requests(), 1u);
}

TEST_F(SourceRequestFixture, ManyAskersEachGetTheirOwnReply) {
  auto laser = make(64);
  ServingLoop loop(*laser);
  std::atomic<int> right = 0;
  {
    std::vector<std::jthread> askers;
    for (std::uint8_t n = 0; n < 8; ++n) {
      askers.emplace_back([&, n] {
        for (int i = 0; i < 20; ++i) {
          const auto reply = ask_source(*laser, {1, n}, 5s);
          if (reply && reply->payload == std::vector<std::uint8_t>{1, n}) ++right;
        }
      });
    }
  }
  EXPECT_EQ(right, 160);
  EXPECT_TRUE(laser->take_replies().empty());
}

}  // namespace source_request_test
}  // namespace playerkit::core
