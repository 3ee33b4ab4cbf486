#include "core/instantiate.hpp"

#include <gtest/gtest.h>

#include "config/errors.hpp"
#include "core/test_drivers.hpp"
#include "protocol/interfaces.hpp"

namespace playerkit::core {
namespace instantiate_test {

using protocol::Access;

struct InstantiateFixture : ::testing::Test {
  void SetUp() override {
    logger.set_sink([](LogLevel, std::string_view) {});
    registry.add(DriverSpec{
        "counting",
        {protocol::kLaserCode, protocol::kSonarCode},
        Access::kRead,
        [this](const DriverContext& context) -> std::unique_ptr<Driver> {
          seen_rate = context.section.read_int("rate", -1);
          seen_robot = context.robot_name;
          return std::make_unique<testing::CountingDriver>(counts);
        },
        DeviceLimits{3},
        "counts calls"});
  }
  config::ConfigFile load(std::string_view text) {
    return config::ConfigFile::parse(text, "test.cfg", load_options_for(registry, 7000));
  }
  testing::CallCounts counts;
  ServerClock clock;
  Logger logger;
  DriverRegistry registry;
  DeviceTable table;
  int seen_rate = 0;
  std::string seen_robot;
};

TEST_F(InstantiateFixture, CreatesOneDevicePerDeclarationWithItsOptions) {
  const auto config = load(
      "laser:1 ( driver \"counting\" rate 20 )\n"
      "robot:7001:bob ( )\n"
      "sonar ( driver \"counting\" alwayson 1 )\n");
  instantiate_devices(config, registry, table, clock, logger);
  ASSERT_EQ(table.size(), 2u);
  const Device* laser = table.find(7000, {protocol::kLaserCode, 1});
  ASSERT_NE(laser, nullptr);
  EXPECT_EQ(laser->info().driver_name, "counting");
  EXPECT_EQ(laser->info().access, Access::kRead);
  EXPECT_EQ(laser->info().limits.request_queue, 3u);
  EXPECT_FALSE(laser->info().alwayson);
  const Device* sonar = table.find(7001, {protocol::kSonarCode, 0});
  ASSERT_NE(sonar, nullptr);
  EXPECT_TRUE(sonar->info().alwayson);
  EXPECT_EQ(sonar->info().robot_name, "bob");
  EXPECT_EQ(seen_robot, "bob");
  EXPECT_EQ(seen_rate, -1);
  EXPECT_TRUE(config.unused_properties().empty());
}

TEST_F(InstantiateFixture, UnknownDriverIsReportedWhereItIsWritten) {
  try {
    load("\nlaser ( driver \"sicklms200\" )\n");
    FAIL() << "expected a ConfigError";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(e.where().line, 2);
    EXPECT_NE(std::string(e.what()).find("sicklms200"), std::string::npos) << e.what();
  }
}

TEST_F(InstantiateFixture, DriverThatDoesNotServeTheInterfaceIsAConfigError) {
  const auto config = load("position ( driver \"counting\" )\n");
  try {
    instantiate_devices(config, registry, table, clock, logger);
    FAIL() << "expected a ConfigError";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.cfg:1:1: driver 'counting' does not serve interface 'position' "
              "(it serves laser, sonar)");
  }
}

TEST_F(InstantiateFixture, FactoryFailureBecomesAConfigErrorAtTheSection) {
  registry.add(DriverSpec{"broken", {protocol::kLaserCode}, Access::kRead,
                          [](const DriverContext&) -> std::unique_ptr<Driver> {
                            throw std::runtime_error("no such port /dev/ttyS9");
                          },
                          {}, ""});
  const auto config = load("\n  laser ( driver \"broken\" )\n");
  try {
    instantiate_devices(config, registry, table, clock, logger);
    FAIL() << "expected a ConfigError";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.cfg:2:3: driver 'broken' could not be created: no such port /dev/ttyS9");
  }
}

TEST_F(InstantiateFixture, AnUnavailableDriverIsRefusedAtItsNameWithItsReason) {
  bool made = false;
  DriverSpec spec{"gone", {protocol::kPositionCode}, Access::kAll,
                  [&made](const DriverContext&) -> std::unique_ptr<Driver> {
                    made = true;
                    return nullptr;
                  },
                  {}, ""};
  spec.doc.unavailable = "its middleware is lost; use \"other\"";
  registry.add(spec);
  const auto config = load("position:0\n(\n  name \"B21R\"\n  driver \"gone\"\n)\n");
  try {
    instantiate_devices(config, registry, table, clock, logger);
    FAIL() << "expected a ConfigError";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()), "test.cfg:4:10: driver 'gone' cannot run: its middleware is lost; use \"other\"");
  }
  EXPECT_FALSE(made);
}

TEST_F(InstantiateFixture, InterfaceLimitsOverrideTheDriversLimitsForThatInterfaceOnly) {
  DriverSpec spec{"counting", {protocol::kLaserCode, protocol::kSonarCode}, Access::kRead,
                  [this](const DriverContext&) -> std::unique_ptr<Driver> {
                    return std::make_unique<testing::CountingDriver>(counts);
                  },
                  DeviceLimits{3}, ""};
  spec.interface_limits[protocol::kSonarCode] = DeviceLimits{5, 16, 4};
  registry.add(std::move(spec));
  instantiate_devices(load("laser ( driver \"counting\" )\nsonar ( driver \"counting\" )\n"),
                      registry, table, clock, logger);
  const Device* laser = table.find(7000, {protocol::kLaserCode, 0});
  const Device* sonar = table.find(7000, {protocol::kSonarCode, 0});
  ASSERT_NE(laser, nullptr);
  ASSERT_NE(sonar, nullptr);
  EXPECT_EQ(laser->info().limits.request_queue, 3u);
  EXPECT_FALSE(laser->queues_data());
  EXPECT_EQ(sonar->info().limits.request_queue, 5u);
  EXPECT_EQ(sonar->info().limits.data_queue, 16u);
  EXPECT_EQ(sonar->info().limits.command_queue, 4u);
}

TEST(DriverRegistryTest, LaterRegistrationReplacesAndListingIsSorted) {
  DriverRegistry registry;
  registry.add({"zeta", {}, Access::kRead, nullptr, {}, "first"});
  registry.add({"alpha", {}, Access::kRead, nullptr, {}, ""});
  registry.add({"zeta", {}, Access::kWrite, nullptr, {}, "second"});
  const auto all = registry.all();
  ASSERT_EQ(all.size(), 2u);
  EXPECT_EQ(all[0]->name, "alpha");
  EXPECT_EQ(all[1]->name, "zeta");
  EXPECT_EQ(registry.find("zeta")->summary, "second");
  EXPECT_EQ(registry.find("nope"), nullptr);
}

// A driver family keeping its own time claims the server clock; the devices
// of one family share one clock, a second family's is refused at its section.
struct ClockClaimFixture : InstantiateFixture {
  void add_claiming_driver(const std::string& name, std::shared_ptr<ManualClock> own_clock) {
    registry.add(DriverSpec{name, {protocol::kLaserCode, protocol::kPositionCode}, Access::kRead,
                            [this, name, own_clock](const DriverContext& context) -> std::unique_ptr<Driver> {
                              context.clock.claim(own_clock, to_string(context.key) + " (" + name + ")");
                              return std::make_unique<testing::CountingDriver>(counts);
                            },
                            {}, ""});
  }
};

TEST_F(ClockClaimFixture, DevicesOfOneFamilyShareTheClockTheyClaim) {
  auto simulation = std::make_shared<ManualClock>(Timestamp{12, 0});
  add_claiming_driver("simulated", simulation);
  instantiate_devices(load("laser ( driver \"simulated\" )\nposition ( driver \"simulated\" )\n"), registry,
                      table, clock, logger);
  EXPECT_EQ(clock.claimant(), "laser:0@7000 (simulated)");
  simulation->advance_microseconds(250'000);
  EXPECT_EQ(clock.now(), (Timestamp{12, 250'000}));
  // Devices stamp what they publish with the server clock.
  Device* laser = table.find(7000, {protocol::kLaserCode, 0});
  ASSERT_NE(laser, nullptr);
  laser->publish({1, 2, 3});
  EXPECT_EQ(laser->latest_data()->timestamp, (Timestamp{12, 250'000}));
}

TEST_F(ClockClaimFixture, ASecondClockIsAConfigErrorAtItsDeviceNamingBoth) {
  add_claiming_driver("replayed", std::make_shared<ManualClock>(Timestamp{1000, 0}));
  add_claiming_driver("simulated", std::make_shared<ManualClock>(Timestamp{0, 0}));
  const auto config = load("laser ( driver \"replayed\" )\n\nposition ( driver \"simulated\" )\n");
  try {
    instantiate_devices(config, registry, table, clock, logger);
    FAIL() << "expected a ConfigError";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(e.where().line, 3);
    const std::string message = e.what();
    EXPECT_NE(message.find("laser:0@7000 (replayed)"), std::string::npos) << message;
    EXPECT_NE(message.find("position:0@7000 (simulated)"), std::string::npos) << message;
  }
}

}  // namespace instantiate_test
}  // namespace playerkit::core
