#include "core/device_table.hpp"

#include <gtest/gtest.h>

#include "core/test_drivers.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::core {
namespace device_table_test {

using protocol::Access;
using testing::CallCounts;
using testing::CountingDriver;

struct DeviceTableFixture : ::testing::Test {
  Device& add(std::uint16_t port, std::uint16_t interface, std::uint16_t index,
              std::string robot = "", bool alwayson = false, bool refuse = false,
              CallCounts* counts_for = nullptr) {
    DeviceInfo info{"counting", std::move(robot), Access::kRead, {}, alwayson};
    return table.add(std::make_unique<Device>(
        DeviceKey{port, {interface, index}}, info,
        std::make_unique<CountingDriver>(counts_for ? *counts_for : counts, refuse), clock, logger));
  }
  CallCounts counts;
  ManualClock clock;
  Logger logger;
  DeviceTable table;
  void SetUp() override { logger.set_sink([](LogLevel, std::string_view) {}); }
};

TEST_F(DeviceTableFixture, LooksUpByPortInterfaceAndIndex) {
  add(6665, protocol::kLaserCode, 0);
  add(6666, protocol::kLaserCode, 0);
  EXPECT_EQ(table.find(6665, {protocol::kLaserCode, 0})->key().port, 6665);
  EXPECT_EQ(table.find(6666, {protocol::kLaserCode, 0})->key().port, 6666);
  EXPECT_EQ(table.find(6667, {protocol::kLaserCode, 0}), nullptr);
  EXPECT_EQ(table.find(6665, {protocol::kLaserCode, 1}), nullptr);
  EXPECT_EQ(table.ports(), (std::vector<std::uint16_t>{6665, 6666}));
}

TEST_F(DeviceTableFixture, KeepsDeclarationOrderAndReplacesInPlace) {
  add(6665, protocol::kPositionCode, 0);
  add(6665, protocol::kLaserCode, 0);
  add(6666, protocol::kSonarCode, 0);
  add(6665, protocol::kPositionCode, 0, "replacement");
  const auto on_6665 = table.on_port(6665);
  ASSERT_EQ(on_6665.size(), 2u);
  EXPECT_EQ(on_6665[0]->address().interface, protocol::kPositionCode);
  EXPECT_EQ(on_6665[0]->info().robot_name, "replacement");
  EXPECT_EQ(on_6665[1]->address().interface, protocol::kLaserCode);
  EXPECT_EQ(table.size(), 3u);
}

TEST_F(DeviceTableFixture, FindsRobotsByExactName) {
  add(6665, protocol::kPositionCode, 0, "bob");
  add(6666, protocol::kPositionCode, 0, "alice");
  ASSERT_NE(table.find_robot("alice"), nullptr);
  EXPECT_EQ(table.find_robot("alice")->key().port, 6666);
  EXPECT_EQ(table.find_robot("Alice"), nullptr);
  EXPECT_EQ(table.find_robot("ali"), nullptr);
}

TEST_F(DeviceTableFixture, AlwaysonDevicesStartAndStopWithTheServer) {
  add(6665, protocol::kLaserCode, 0, "", /*alwayson=*/true);
  add(6665, protocol::kSonarCode, 0);
  table.start_alwayson();
  EXPECT_EQ(counts.setup, 1);
  EXPECT_EQ(table.find(6665, {protocol::kLaserCode, 0})->subscriptions(), 1);
  table.shutdown_all();
  EXPECT_EQ(counts.shutdown, 1);
}

TEST_F(DeviceTableFixture, AlwaysonSetupFailureNamesTheDevice) {
  add(6665, protocol::kLaserCode, 2, "", /*alwayson=*/true, /*refuse=*/true);
  try {
    table.start_alwayson();
    FAIL() << "expected an error";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("laser:2@6665"), std::string::npos) << e.what();
  }
}

TEST_F(DeviceTableFixture, PrepareReachesEveryDevice) {
  add(6665, protocol::kLaserCode, 0);
  add(6665, protocol::kSonarCode, 0);
  table.prepare_all();
  EXPECT_EQ(counts.prepare, 2);
}

}  // namespace device_table_test
}  // namespace playerkit::core

namespace playerkit::core {
namespace device_table_test {

// A driver built on another device (as amcl uses a laser): it holds a
// subscription on it exactly while it is itself subscribed.
class DependentDriver : public Driver {
 public:
  explicit DependentDriver(Device& source) : source_(source) {}
  void setup() override {
    if (!source_.subscribe()) throw DriverError("source unavailable");
  }
  void shutdown() override { source_.unsubscribe(); }

 private:
  Device& source_;
};

TEST_F(DeviceTableFixture, DriversMaySubscribeToOtherDevices) {
  Device& laser = add(6665, protocol::kLaserCode, 0);
  Device& localize = table.add(std::make_unique<Device>(
      DeviceKey{6665, {protocol::kLocalizeCode, 0}}, DeviceInfo{"dependent", "", Access::kRead, {}, false},
      std::make_unique<DependentDriver>(laser), clock, logger));
  ASSERT_TRUE(localize.subscribe());
  EXPECT_EQ(laser.subscriptions(), 1);
  EXPECT_EQ(counts.setup, 1);
  localize.unsubscribe();
  EXPECT_EQ(laser.subscriptions(), 0);
  EXPECT_EQ(counts.shutdown, 1);
  // At exit the dependent device goes first, then the one it used.
  ASSERT_TRUE(localize.subscribe());
  table.shutdown_all();
  EXPECT_EQ(laser.subscriptions(), 0);
  EXPECT_EQ(counts.shutdown, 2);
}

// What a table's destruction did, seen by the drivers of a source device and
// of a device built on it.
struct Lifetimes {
  bool source_destroyed = false;
  bool dependent_shut_down = false;
  bool source_alive_at_dependent_shutdown = false;
};

class WatchedSourceDriver : public Driver {
 public:
  explicit WatchedSourceDriver(Lifetimes& lifetimes) : lifetimes_(lifetimes) {}
  ~WatchedSourceDriver() override { lifetimes_.source_destroyed = true; }

 private:
  Lifetimes& lifetimes_;
};

class WatchingDependentDriver : public Driver {
 public:
  WatchingDependentDriver(Device& source, Lifetimes& lifetimes) : source_(source), lifetimes_(lifetimes) {}
  void setup() override {
    if (!source_.subscribe()) throw DriverError("source unavailable");
  }
  void shutdown() override {
    lifetimes_.dependent_shut_down = true;
    lifetimes_.source_alive_at_dependent_shutdown = !lifetimes_.source_destroyed;
    // Touching a destroyed source is the bug this watches for; skip it then.
    if (!lifetimes_.source_destroyed) source_.unsubscribe();
  }

 private:
  Device& source_;
  Lifetimes& lifetimes_;
};

// A table destroyed without shutdown_all() (a test fixture, an exception
// unwinding a daemon) shut its devices down in declaration order: the laser
// was destroyed while amcl still held it, and amcl's shutdown then touched
// freed memory (AddressSanitizer, drivers_amcl_test).
TEST_F(DeviceTableFixture, DestructionShutsDownDependentsBeforeTheirSources) {
  Lifetimes lifetimes;
  {
    DeviceTable local;
    Device& laser = local.add(std::make_unique<Device>(
        DeviceKey{6665, {protocol::kLaserCode, 0}}, DeviceInfo{"watched", "", Access::kRead, {}, false},
        std::make_unique<WatchedSourceDriver>(lifetimes), clock, logger));
    Device& localize = local.add(std::make_unique<Device>(
        DeviceKey{6665, {protocol::kLocalizeCode, 0}}, DeviceInfo{"dependent", "", Access::kRead, {}, false},
        std::make_unique<WatchingDependentDriver>(laser, lifetimes), clock, logger));
    ASSERT_TRUE(localize.subscribe());
    ASSERT_EQ(laser.subscriptions(), 1);
  }
  EXPECT_TRUE(lifetimes.dependent_shut_down);
  EXPECT_TRUE(lifetimes.source_alive_at_dependent_shutdown);
  EXPECT_TRUE(lifetimes.source_destroyed);
}

}  // namespace device_table_test
}  // namespace playerkit::core
