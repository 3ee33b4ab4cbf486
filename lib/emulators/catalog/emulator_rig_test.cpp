// The rig with toy kinds made here: any robot carries any rider, whatever
// family either comes from. The real Pioneer with a SICK laser on its back is
// tested in tests/hardware/pioneer_rig_test.cpp.

#include "emulators/catalog/emulator_rig.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>

#include "emulators/emulator_option_reader.hpp"

namespace playerkit::emulators {
namespace emulator_rig_test {

// Says nothing; the toys differ in where they are.
class QuietDevice : public DeviceEmulator {
 public:
  void receive(std::span<const std::uint8_t>, Duration, int) override {}
  void advance(Duration) override {}
  [[nodiscard]] Duration next_deadline() const override { return Duration::max(); }
  std::vector<Telegram> take_output() override { return {}; }
};

// A mobile base at the pose it holds.
class ToyRobot final : public QuietDevice {
 public:
  explicit ToyRobot(geometry::Pose2 pose) : pose_(pose) {}
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return pose_; }
  [[nodiscard]] std::string describe() const override { return "toy robot at x=" + std::to_string(pose_.x); }
  void move_to(geometry::Pose2 pose) { pose_ = pose; }

 private:
  geometry::Pose2 pose_;
};

// A sensor that keeps the carrier its world gave it, and the map.
class ToyRider final : public QuietDevice {
 public:
  explicit ToyRider(const EmulatorWorld& world) : world_(world) {}
  [[nodiscard]] std::string describe() const override { return world_.carrier_pose ? "carried" : "alone"; }
  [[nodiscard]] bool has_carrier() const { return static_cast<bool>(world_.carrier_pose); }
  // Asks the carrier, as a real rider does at every scan.
  [[nodiscard]] geometry::Pose2 carrier_pose() const { return world_.carrier_pose(); }
  [[nodiscard]] const grid::OccupancyGrid* map() const { return world_.map; }

 private:
  EmulatorWorld world_;
};

// Neither carries nor rides.
class ToyBox final : public QuietDevice {
 public:
  [[nodiscard]] std::string describe() const override { return "a box"; }
  // Not a robot: the rig must not ask it all the same.
  [[nodiscard]] std::optional<geometry::Pose2> world_pose() const override { return geometry::Pose2{-9, -9, 0}; }
};

EmulatorKind robot_kind(const std::string& name) {
  return {.name = name,
          .summary = "a toy robot",
          .interface_name = "position",
          .driver = name + "_position",
          .mount = EmulatorMount::robot,
          .options = {{"x", "0", "where it stands, m"}},
          .make = [](const EmulatorOptionReader& options, const EmulatorWorld&) {
            return std::unique_ptr<DeviceEmulator>(
                std::make_unique<ToyRobot>(geometry::Pose2{options.number("x", 0.0, -100.0, 100.0), 0.0, 0.0}));
          }};
}

EmulatorKind rider_kind(const std::string& name) {
  return {.name = name,
          .summary = "a toy sensor",
          .interface_name = "ranger",
          .driver = name,
          .mount = EmulatorMount::rider,
          .options = {},
          .make = [](const EmulatorOptionReader&, const EmulatorWorld& world) {
            return std::unique_ptr<DeviceEmulator>(std::make_unique<ToyRider>(world));
          }};
}

EmulatorKind box_kind(const std::string& name) {
  return {.name = name,
          .summary = "a toy box",
          .interface_name = "dio",
          .driver = name,
          .mount = EmulatorMount::standalone,
          .options = {},
          .make = [](const EmulatorOptionReader&, const EmulatorWorld&) {
            return std::unique_ptr<DeviceEmulator>(std::make_unique<ToyBox>());
          }};
}

// Two robots and two riders, as two families would bring them, and a box.
EmulatorCatalog toys() {
  return EmulatorCatalog({robot_kind("rover"), rider_kind("lidar"), robot_kind("crawler"), rider_kind("sonar"),
                          box_kind("crate")});
}

bool rides(EmulatorRig& rig, std::size_t index) {
  return rig.runner(index).with_emulator<ToyRider>([](ToyRider& rider) { return rider.has_carrier(); });
}

double carrier_x(EmulatorRig& rig, std::size_t index) {
  return rig.runner(index).with_emulator<ToyRider>([](ToyRider& rider) { return rider.carrier_pose().x; });
}

std::filesystem::path temp_link(const std::string& what) {
  return std::filesystem::temp_directory_path() /
         ("emulator_rig_test_" + std::to_string(::getpid()) + "_" + what);
}

TEST(EmulatorRig, AnyRobotCarriesAnyRider) {
  for (const std::string robot : {"rover", "crawler"}) {
    for (const std::string rider : {"lidar", "sonar"}) {
      EmulatorRig rig(toys(), {{robot, {{"x", "1.5"}}, PtyEndpoint{}}, {rider, {}, PtyEndpoint{}}}, {});
      ASSERT_EQ(rig.size(), 2u);
      EXPECT_FALSE(rig.carried(0)) << robot << " " << rider;
      EXPECT_TRUE(rig.carried(1)) << robot << " " << rider;
      ASSERT_TRUE(rides(rig, 1)) << robot << " " << rider;
      EXPECT_DOUBLE_EQ(carrier_x(rig, 1), 1.5) << robot << " " << rider;
    }
  }
}

TEST(EmulatorRig, ARiderFollowsItsRobotsTruePose) {
  EmulatorRig rig(toys(), {{"crawler", {}, PtyEndpoint{}}, {"lidar", {}, PtyEndpoint{}}}, {});
  EXPECT_DOUBLE_EQ(carrier_x(rig, 1), 0.0);
  rig.runner(0).with_emulator<ToyRobot>([](ToyRobot& robot) { robot.move_to({4.0, 1.0, 0.0}); });
  EXPECT_DOUBLE_EQ(carrier_x(rig, 1), 4.0);
}

TEST(EmulatorRig, RidersListedFirstStillRideAndAllOnTheFirstRobot) {
  // The riders come first and two robots follow: the robots are started
  // first all the same, and every rider rides on the first robot listed.
  EmulatorRig rig(toys(),
                  {{"sonar", {}, PtyEndpoint{}},
                   {"crawler", {{"x", "2"}}, PtyEndpoint{}},
                   {"lidar", {}, PtyEndpoint{}},
                   {"rover", {{"x", "-3"}}, PtyEndpoint{}}},
                  {});
  ASSERT_EQ(rig.size(), 4u);
  EXPECT_EQ(rig.kind(0).name, "sonar");
  EXPECT_EQ(rig.kind(1).name, "crawler");
  EXPECT_TRUE(rig.carried(0));
  EXPECT_FALSE(rig.carried(1));
  EXPECT_TRUE(rig.carried(2));
  EXPECT_FALSE(rig.carried(3));
  EXPECT_DOUBLE_EQ(carrier_x(rig, 0), 2.0);
  EXPECT_DOUBLE_EQ(carrier_x(rig, 2), 2.0);
}

TEST(EmulatorRig, RidersWithoutARobotStandAlone) {
  // A box is no robot: it carries nothing.
  EmulatorRig rig(toys(), {{"crate", {}, PtyEndpoint{}}, {"lidar", {}, PtyEndpoint{}}, {"sonar", {}, PtyEndpoint{}}},
                  {});
  ASSERT_EQ(rig.size(), 3u);
  for (std::size_t i = 0; i < rig.size(); ++i) EXPECT_FALSE(rig.carried(i)) << i;
  EXPECT_FALSE(rides(rig, 1));
  EXPECT_FALSE(rides(rig, 2));
  EXPECT_EQ(rig.describe(1), "alone");
  EXPECT_EQ(rig.describe(0), "a box");
}

TEST(EmulatorRig, EveryMemberSharesTheMap) {
  auto map = std::make_shared<const grid::OccupancyGrid>(grid::OccupancyGrid::centred(20, 20, 0.1, grid::CellState::free));
  EmulatorRig rig(toys(), {{"lidar", {}, PtyEndpoint{}}}, {.map = map, .faults = {}});
  EXPECT_EQ(rig.runner(0).with_emulator<ToyRider>([](ToyRider& rider) { return rider.map(); }), map.get());
}

TEST(EmulatorRig, ConfigLinesAndDescriptionsAreEachMembers) {
  EmulatorRig rig(toys(), {{"sonar", {}, PtyEndpoint{}}, {"rover", {{"x", "1"}}, PtyEndpoint{}}}, {});
  EXPECT_EQ(rig.config_line(0), "ranger:0 ( driver \"sonar\" port \"" + rig.runner(0).device_path() + "\" )");
  EXPECT_EQ(rig.config_line(1), "position:0 ( driver \"rover_position\" port \"" + rig.runner(1).device_path() + "\" )");
  EXPECT_EQ(rig.describe(0), "carried");
  EXPECT_EQ(rig.describe(1), "toy robot at x=1.000000");
  EXPECT_THROW((void)rig.config_line(2), std::out_of_range);
}

TEST(EmulatorRig, SymlinksAndTcpPortsAreTheLinesAsked) {
  const auto link = temp_link("robot");
  {
    EmulatorRig rig(toys(), {{"rover", {}, PtyEndpoint{link}}, {"sonar", {}, TcpEndpoint{}}}, {});
    EXPECT_EQ(rig.runner(0).device_path(), link.string());
    EXPECT_TRUE(std::filesystem::is_symlink(link));
    EXPECT_EQ(rig.runner(1).device_path().rfind("tcp:127.0.0.1:", 0), 0u) << rig.runner(1).device_path();
    // A rider on a TCP port rides all the same.
    EXPECT_TRUE(rig.carried(1));
  }
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

TEST(EmulatorRig, ABadRequestStartsNothing) {
  const auto link = temp_link("first");
  // An unknown name, even the last one.
  try {
    EmulatorRig rig(toys(), {{"rover", {}, PtyEndpoint{link}}, {"lidr", {}, PtyEndpoint{}}}, {});
    ADD_FAILURE() << "started";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "no emulator 'lidr'; there are rover, lidar, crawler, sonar, crate");
  }
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
  // A bad option of a rider started after the robot.
  EXPECT_THROW(EmulatorRig(toys(), {{"rover", {}, PtyEndpoint{link}}, {"lidar", {{"x", "1"}}, PtyEndpoint{}}}, {}),
               std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
  // A bad value of a robot.
  EXPECT_THROW(EmulatorRig(toys(), {{"lidar", {}, PtyEndpoint{link}}, {"rover", {{"x", "far"}}, PtyEndpoint{}}}, {}),
               std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

TEST(EmulatorRig, TheCatalogNeedNotOutliveTheRig) {
  std::optional<EmulatorRig> rig;
  rig.emplace(toys(), std::vector<EmulatorRequest>{{"rover", {}, PtyEndpoint{}}, {"sonar", {}, PtyEndpoint{}}},
              RigSettings{});
  EXPECT_EQ(rig->kind(1).name, "sonar");
  EXPECT_EQ(rig->config_line(0), "position:0 ( driver \"rover_position\" port \"" + rig->runner(0).device_path() + "\" )");
}

}  // namespace emulator_rig_test
}  // namespace playerkit::emulators
