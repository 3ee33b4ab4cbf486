#include "drivers/sim/sim_drivers.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "config/errors.hpp"
#include "drivers/sim/sim_test_support.hpp"
#include "drivers/sim/world_configuration.hpp"
#include "sim/worldfile/world_loader.hpp"

namespace playerkit::drivers::sim {
namespace sim_drivers_test {

using namespace testing;

World laser_robot_world() {
  World world({.step = 0.1, .seed = 1}, open_floor());
  const ModelId robot = world.add(test_robot("robot"));
  world.add(on(robot, "robot.laser", test_laser()));
  return world;
}

std::string load_error(SimDevices& sim, const std::string& config) {
  try {
    sim.load(config);
  } catch (const config::ConfigError& e) {
    return e.what();
  }
  return "no error";
}

TEST(SimDriversTest, WithoutAWorldADeviceIsRefusedSayingHowToGiveOne) {
  drivers::testing::BuiltinDevices builtin;
  try {
    builtin.load("\nposition:0 ( driver \"gz_position\" gz_id \"robot\" )\n");
    FAIL() << "created without a world";
  } catch (const config::ConfigError& e) {
    EXPECT_EQ(std::string(e.what()),
              "test.cfg:2:1: gz_position: no simulated world to serve: start player-serve with -s WORLD");
  }
}

TEST(SimDriversTest, AModelThatIsNotThereIsAnErrorAtTheOption) {
  SimDevices sim{laser_robot_world()};
  EXPECT_EQ(load_error(sim, "laser:0 ( driver \"gz_laser\" gz_id \"robto\" )\n"),
            "test.cfg:1:35: gz_laser: the world has no model named \"robto\"");
  EXPECT_EQ(load_error(sim, "position:0 ( driver \"gz_position\" gz_id \"robot.laser\" )\n"),
            "test.cfg:1:41: gz_position: model \"robot.laser\" is no position and carries none");
  EXPECT_EQ(load_error(sim, "laser:0 ( driver \"laser\" )\n"),
            "test.cfg:1:1: laser: needs model, the name of a model in test.world");
}

TEST(SimDriversTest, EverySimulatedDeviceClaimsTheSimulationClock) {
  SimDevices sim{laser_robot_world()};
  sim.load("position:0 ( driver \"position\" model \"robot\" )\nlaser:0 ( driver \"laser\" model \"robot\" )\n");
  EXPECT_EQ(sim.builtin.clock.claimant(), "position:0@6665 (position)");
  sim.step(7);
  EXPECT_EQ(sim.builtin.clock.now(), (protocol::Timestamp{0, 700000}));
}

TEST(SimDriversTest, ASecondClockIsAConfigErrorNamingBothDevices) {
  SimDevices sim{laser_robot_world()};
  auto other = std::make_shared<core::ManualClock>(protocol::Timestamp{1000, 0});
  core::DriverSpec replay;
  replay.name = "replayed";
  replay.interfaces = {protocol::kLaserCode};
  replay.factory = [other](const core::DriverContext& context) -> std::unique_ptr<core::Driver> {
    context.clock.claim(other, core::to_string(context.key) + " (replayed)");
    return std::make_unique<core::Driver>();
  };
  sim.builtin.registry.add(replay);
  const std::string error = load_error(sim, "laser:1 ( driver \"replayed\" )\nlaser:0 ( driver \"laser\" model \"robot\" )\n");
  EXPECT_NE(error.find("test.cfg:2:1:"), std::string::npos) << error;
  EXPECT_NE(error.find("laser:1@6665 (replayed)"), std::string::npos) << error;
  EXPECT_NE(error.find("laser:0@6665 (laser)"), std::string::npos) << error;
}

TEST(SimDriversTest, EveryNameIsDocumented) {
  const auto specs = simulation_driver_specs(nullptr);
  for (const char* name : {"position", "laser", "sonar", "fiducialfinder", "lbd", "blobfinder", "vision", "ptz",
                           "gripper", "power", "truth", "gz_position", "gz_laser", "gz_sonars", "gz_fiducial",
                           "gz_truth", "gz_gripper", "gz_ptz", "gz_power", "simulation"}) {
    const auto found =
        std::find_if(specs.begin(), specs.end(), [&](const core::DriverSpec& spec) { return spec.name == name; });
    ASSERT_NE(found, specs.end()) << name;
    EXPECT_FALSE(found->summary.empty()) << name;
    EXPECT_FALSE(found->doc.example.empty()) << name;
  }
}

// -s: every device of the example worlds is served by a simulated driver.
struct ExampleWorldTest : ::testing::TestWithParam<std::string> {};

TEST_P(ExampleWorldTest, EveryDeviceOfTheWorldIsMadeOnItsPort) {
  const std::filesystem::path file = std::filesystem::path(PLAYERKIT_WORLDS_DIR) / GetParam();
  auto loaded = playerkit::sim::worldfile::load_world(file, {.seed = 3, .default_port = kTestPort});
  const std::string text = world_configuration(loaded.world, loaded.devices, kTestPort);
  SimDevices sim{std::move(loaded.world)};
  ASSERT_NO_THROW(sim.load(text)) << text;
  ASSERT_EQ(sim.builtin.devices.size(), loaded.devices.size() + 1) << text;  // and the simulation control
  for (const auto& device : loaded.devices) {
    const core::Device* made = sim.builtin.devices.find(device.port, {device.interface_code, device.index});
    ASSERT_NE(made, nullptr) << text;
    EXPECT_EQ(made->info().driver_name, world_device_driver(device));
  }
  EXPECT_NE(sim.builtin.devices.find(kTestPort, {protocol::kSimulationCode, 0}), nullptr);
  // Every device can be set up and publishes after a step.
  auto all = sim.builtin.devices.all();
  for (core::Device* device : all) ASSERT_TRUE(device->subscribe()) << device->name();
  sim.step(10);
  for (core::Device* device : all) {
    device->update();
    EXPECT_GT(device->latest_data()->sequence, 0u) << device->name();
  }
  for (core::Device* device : all) device->unsubscribe();
}

INSTANTIATE_TEST_SUITE_P(DataWorlds, ExampleWorldTest,
                         ::testing::Values("simple.world", "example-13.world", "example-4a.world", "example-4b.world"));

TEST(WorldConfigurationTest, RobotsOnTheirPortsInWorldOrder) {
  const std::filesystem::path file = std::filesystem::path(PLAYERKIT_WORLDS_DIR) / "example-13.world";
  const auto loaded = playerkit::sim::worldfile::load_world(file, {.default_port = 7000});
  const std::string text = world_configuration(loaded.world, loaded.devices, 7000);
  EXPECT_EQ(text.find("robot:6665 ( )\nposition:0 ( driver \"position\" model \"robot1\" )\n"), 0u) << text;
  EXPECT_NE(text.find("robot:6666 ( )\nposition:0 ( driver \"position\" model \"robot2\" )\n"), std::string::npos)
      << text;
  EXPECT_NE(text.find("robot:7000 ( )\nsimulation:0 ( driver \"simulation\" alwayson 1 )\n"), std::string::npos)
      << text;
}

}  // namespace sim_drivers_test
}  // namespace playerkit::drivers::sim
