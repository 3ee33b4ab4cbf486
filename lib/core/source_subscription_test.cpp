#include "core/source_subscription.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "core/test_drivers.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::core {
namespace source_subscription_test {

struct CountingListener : DeviceListener {
  int data = 0;
  void data_published(const Device&) override { ++data; }
  void replies_ready(const Device&) override {}
};

struct SourceSubscriptionFixture : ::testing::Test {
  std::unique_ptr<Device> make(testing::CallCounts& counts, bool refuse = false) {
    DeviceInfo info{"counting", "", protocol::Access::kAll, DeviceLimits{}, false};
    return std::make_unique<Device>(DeviceKey{6665, {protocol::kLaserCode, 0}}, info,
                                    std::make_unique<testing::CountingDriver>(counts, refuse), clock,
                                    logger);
  }
  void SetUp() override { logger.set_sink([](LogLevel, std::string_view) {}); }
  ManualClock clock;
  Logger logger;
};

TEST_F(SourceSubscriptionFixture, SubscribesListensAndUndoesBoth) {
  testing::CallCounts counts;
  auto laser = make(counts);
  CountingListener listener;
  {
    SourceSubscription subscription(*laser, &listener, "amcl");
    EXPECT_EQ(laser->subscriptions(), 1);
    laser->publish({1, 2, 3});
    EXPECT_EQ(listener.data, 1);
  }
  EXPECT_EQ(laser->subscriptions(), 0);
  EXPECT_EQ(counts.shutdown, 1);
  laser->publish({4});
  EXPECT_EQ(listener.data, 1);  // no longer listening
}

TEST_F(SourceSubscriptionFixture, ARefusedSourceThrowsAndLeavesNothingBehind) {
  testing::CallCounts counts;
  auto laser = make(counts, true);
  CountingListener listener;
  try {
    SourceSubscription subscription(*laser, &listener, "amcl");
    FAIL() << "expected DriverError";
  } catch (const DriverError& error) {
    EXPECT_NE(std::string(error.what()).find("amcl: laser:0@6665"), std::string::npos) << error.what();
  }
  EXPECT_EQ(laser->subscriptions(), 0);
  laser->publish({1});
  EXPECT_EQ(listener.data, 0);
}

TEST_F(SourceSubscriptionFixture, FailingHalfwayReleasesTheOnesAlreadyTaken) {
  testing::CallCounts good_counts, bad_counts;
  auto odometry = make(good_counts);
  auto laser = make(bad_counts, true);
  std::vector<SourceSubscription> taken;
  EXPECT_THROW(
      {
        taken.emplace_back(*odometry, nullptr, "amcl");
        std::vector<SourceSubscription> attempt = std::move(taken);
        attempt.emplace_back(*laser, nullptr, "amcl");
        taken = std::move(attempt);
      },
      DriverError);
  EXPECT_EQ(odometry->subscriptions(), 0);
  EXPECT_EQ(good_counts.shutdown, 1);
}

TEST_F(SourceSubscriptionFixture, StopListeningKeepsTheSubscription) {
  testing::CallCounts counts;
  auto laser = make(counts);
  CountingListener listener;
  SourceSubscription subscription(*laser, &listener, "writelog");
  subscription.stop_listening();
  laser->publish({1});
  EXPECT_EQ(listener.data, 0);
  EXPECT_EQ(laser->subscriptions(), 1);
  subscription.reset();
  EXPECT_EQ(laser->subscriptions(), 0);
  EXPECT_FALSE(subscription);
}

}  // namespace source_subscription_test
}  // namespace playerkit::core
