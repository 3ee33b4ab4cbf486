#include "server/subscription_table.hpp"

#include <gtest/gtest.h>

#include "core/test_drivers.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::server {
namespace subscription_table_test {

struct SubscriptionFixture : ::testing::Test {
  void SetUp() override { logger.set_sink([](core::LogLevel, std::string_view) {}); }
  std::unique_ptr<core::Device> make_device(bool refuse = false) {
    return std::make_unique<core::Device>(
        core::DeviceKey{6665, {protocol::kSonarCode, 0}},
        core::DeviceInfo{"counting", "", Access::kRead, {}, false},
        std::make_unique<core::testing::CountingDriver>(counts, refuse), clock, logger);
  }
  Access ask(char letter) { return table.request(address, static_cast<std::uint8_t>(letter), device.get()); }

  core::testing::CallCounts counts;
  core::ManualClock clock;
  core::Logger logger;
  std::unique_ptr<core::Device> device = make_device();
  DeviceAddress address{protocol::kSonarCode, 0};
  SubscriptionTable table;
};

// Each row of server-behaviour.md §3.1, walked in one sequence.
TEST_F(SubscriptionFixture, FollowsThe15AccessTable) {
  EXPECT_EQ(table.access(address), Access::kError);
  EXPECT_EQ(ask('c'), Access::kError);  // closing what was never open: unchanged
  EXPECT_EQ(device->subscriptions(), 0);
  EXPECT_EQ(ask('r'), Access::kRead);
  EXPECT_EQ(device->subscriptions(), 1);
  EXPECT_EQ(ask('r'), Access::kRead);  // same again: nothing
  EXPECT_EQ(device->subscriptions(), 1);
  EXPECT_EQ(ask('w'), Access::kWrite);  // r -> w: nothing to count
  EXPECT_EQ(device->subscriptions(), 1);
  EXPECT_EQ(ask('a'), Access::kAll);  // one more
  EXPECT_EQ(device->subscriptions(), 2);
  EXPECT_EQ(ask('r'), Access::kRead);  // a -> r: one less
  EXPECT_EQ(device->subscriptions(), 1);
  EXPECT_EQ(ask('a'), Access::kAll);
  EXPECT_EQ(ask('c'), Access::kClose);  // a -> c: two less
  EXPECT_EQ(device->subscriptions(), 0);
  EXPECT_EQ(counts.setup, 1);
  EXPECT_EQ(counts.shutdown, 1);
  EXPECT_EQ(ask('c'), Access::kClose);  // already closed
  EXPECT_EQ(ask('a'), Access::kAll);  // c -> a: two
  EXPECT_EQ(device->subscriptions(), 2);
  EXPECT_EQ(ask('w'), Access::kWrite);
  EXPECT_EQ(ask('c'), Access::kClose);
  EXPECT_EQ(device->subscriptions(), 0);
  EXPECT_EQ(table.entries().size(), 1u);  // the entry stays after close
}

TEST_F(SubscriptionFixture, OtherBytesChangeNothing) {
  EXPECT_EQ(ask('x'), Access::kError);
  EXPECT_EQ(ask('r'), Access::kRead);
  EXPECT_EQ(ask('e'), Access::kRead);
  EXPECT_EQ(device->subscriptions(), 1);
}

TEST_F(SubscriptionFixture, MissingDeviceOrRefusedSetupGivesE) {
  EXPECT_EQ(table.request(address, 'r', nullptr), Access::kError);
  device = make_device(/*refuse=*/true);
  EXPECT_EQ(ask('a'), Access::kError);
  EXPECT_EQ(device->subscriptions(), 0);
}

// A set-up device whose driver lost its resource (passthrough's remote server).
TEST_F(SubscriptionFixture, UnavailableDeviceGivesENewcomersAndKeepsHolders) {
  EXPECT_EQ(ask('r'), Access::kRead);
  device->set_available(false, "remote gone");
  SubscriptionTable newcomer;
  EXPECT_EQ(newcomer.request(address, 'r', device.get()), Access::kError);
  EXPECT_EQ(table.access(address), Access::kRead);
  EXPECT_EQ(device->subscriptions(), 1);
  device->set_available(true);
  EXPECT_EQ(newcomer.request(address, 'r', device.get()), Access::kRead);
  EXPECT_EQ(device->subscriptions(), 2);
}

TEST_F(SubscriptionFixture, EntriesKeepFirstRequestOrder) {
  table.request({protocol::kLaserCode, 0}, 'r', nullptr);
  ask('r');
  table.request({protocol::kLaserCode, 0}, 'c', nullptr);
  ASSERT_EQ(table.entries().size(), 2u);
  EXPECT_EQ(table.entries()[0].device.interface, protocol::kLaserCode);
  EXPECT_EQ(table.entries()[1].device.interface, protocol::kSonarCode);
}

}  // namespace subscription_table_test
}  // namespace playerkit::server
