#include "drivers/sim/simulation_host.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <limits>
#include <thread>

#include "drivers/sim/sim_test_support.hpp"

namespace playerkit::drivers::sim {
namespace simulation_host_test {

using namespace testing;
using drivers::testing::eventually;

World empty_world() {
  World world({.step = 0.1, .seed = 1}, open_floor());
  world.add(test_robot("robot"));
  return world;
}

SimulationSettings settings(double speedup, std::optional<double> run_limit = std::nullopt) {
  return {.speedup = speedup, .run_limit = run_limit, .start_paused = false};
}

core::Logger& quiet_logger() {
  static core::Logger logger;
  logger.set_sink([](core::LogLevel, std::string_view) {});
  return logger;
}

TEST(SimulationHostTest, TheClockStartsAtZeroAndFollowsTheSteps) {
  SimulationHost host(empty_world(), "test.world", stepped_by_hand(), quiet_logger());
  EXPECT_EQ(host.clock()->now(), (protocol::Timestamp{0, 0}));
  for (int i = 0; i < 15; ++i) host.step();
  EXPECT_DOUBLE_EQ(host.time(), 1.5);
  EXPECT_EQ(host.clock()->now(), (protocol::Timestamp{1, 500000}));
}

TEST(SimulationHostTest, AsFastAsPossibleStopsAtTheRunLimit) {
  SimulationHost host(empty_world(), "test.world", settings(0.0, 3.0), quiet_logger());
  host.start();
  ASSERT_TRUE(eventually([&] { return host.run_limit_reached(); }));
  // Stopped at the step that reached it, not one later.
  EXPECT_EQ(host.with_world([](World& world) { return world.steps(); }), 30u);
  EXPECT_EQ(host.clock()->now(), (protocol::Timestamp{3, 0}));
  host.step();  // by hand it still goes on
  EXPECT_EQ(host.with_world([](World& world) { return world.steps(); }), 31u);
}

TEST(SimulationHostTest, APausedWorldStandsStill) {
  SimulationHost host(empty_world(), "test.world", settings(0.0), quiet_logger());
  host.start();
  ASSERT_TRUE(eventually([&] { return host.time() > 0.5; }));
  host.pause();
  // The world lock waits out a step under way.
  const auto steps = host.with_world([](World& world) { return world.steps(); });
  std::this_thread::sleep_for(std::chrono::milliseconds(30));
  EXPECT_EQ(host.with_world([](World& world) { return world.steps(); }), steps);
  host.step();
  EXPECT_EQ(host.with_world([](World& world) { return world.steps(); }), steps + 1);
  EXPECT_TRUE(host.paused());
  host.resume();
  ASSERT_TRUE(eventually([&] { return host.with_world([](World& world) { return world.steps(); }) > steps + 10; }));
}

TEST(SimulationHostTest, ActivationIsCountedPerModel) {
  SimulationHost host(empty_world(), "test.world", stepped_by_hand(), quiet_logger());
  const auto active = [&] { return host.with_world([](World& world) { return world.active(0); }); };
  host.activate(0);
  host.activate(0);
  host.deactivate(0);
  EXPECT_TRUE(active());
  host.deactivate(0);
  EXPECT_FALSE(active());
  host.deactivate(0);  // one too many: ignored
  EXPECT_FALSE(active());
}

TEST(SimulationHostTest, NegativeOrNonFiniteSettingsAreRefused) {
  EXPECT_THROW(SimulationHost(empty_world(), "w", settings(-1.0), quiet_logger()), std::invalid_argument);
  EXPECT_THROW(SimulationHost(empty_world(), "w", settings(std::numeric_limits<double>::infinity()), quiet_logger()),
               std::invalid_argument);
  EXPECT_THROW(SimulationHost(empty_world(), "w", settings(1.0, -2.0), quiet_logger()), std::invalid_argument);
}

TEST(SimulationTimestampTest, WholeMicroseconds) {
  EXPECT_EQ(simulation_timestamp(0.0), (protocol::Timestamp{0, 0}));
  EXPECT_EQ(simulation_timestamp(2.0000000000000004), (protocol::Timestamp{2, 0}));
  EXPECT_EQ(simulation_timestamp(12.3456789), (protocol::Timestamp{12, 345679}));
}

}  // namespace simulation_host_test
}  // namespace playerkit::drivers::sim
