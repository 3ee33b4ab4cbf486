// The er1 family as the tools see it: its emulator kind (a robot others can
// ride on) and its probe, against the emulated ER1 on a pseudo-terminal.

#include "families/er1/er1_family.hpp"

#include <gtest/gtest.h>

#include <string>

#include "emulators/catalog/emulator_catalog.hpp"
#include "emulators/runner/emulator_runner.hpp"
#include "families/family_registry.hpp"
#include "families/port_probe.hpp"

namespace playerkit::families {
namespace {

emulators::EmulatorCatalog catalog() { return emulators::EmulatorCatalog(er1_family().emulators); }

std::string refusal(const emulators::EmulatorOptionValues& options) {
  try {
    (void)catalog().make("er1", options, {});
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(Er1Family, OffersTheRobotAsAMountForSensors) {
  const emulators::EmulatorCatalog kinds = catalog();
  const emulators::EmulatorKind* robot = kinds.find("er1");
  ASSERT_NE(robot, nullptr);
  EXPECT_EQ(robot->mount, emulators::EmulatorMount::robot);
  EXPECT_EQ(config_example(*robot, "/tmp/er1"), "position:0 ( driver \"er1_position\" port \"/tmp/er1\" )");
  for (const char* shared : {"pose", "odometry_scale", "rotation_scale", "drift", "seed", "axle", "motor_dir"}) {
    bool found = false;
    for (const auto& option : robot->options) found = found || option.name == shared;
    EXPECT_TRUE(found) << shared;
  }
  const auto placed = catalog().make("er1", {{"pose", "1,2,90"}}, {});
  ASSERT_TRUE(placed->world_pose());
  EXPECT_NEAR(placed->world_pose()->x, 1.0, 1e-9);
  EXPECT_NEAR(placed->world_pose()->yaw, 3.14159265358979 / 2, 1e-9);
}

TEST(Er1Family, RefusesWiringsAndAxlesARobotCannotHave) {
  EXPECT_NE(refusal({{"motor_dir", "0"}}).find("motor_dir"), std::string::npos);
  EXPECT_NE(refusal({{"axle", "0"}}).find("axle"), std::string::npos);
  EXPECT_EQ(refusal({{"motor_dir", "-1"}, {"axle", "0.4"}, {"odometry_scale", "0.02"}}), "");
}

TEST(Er1Family, TheProbeFindsTheControllerAndPrintsItsSection) {
  emulators::EmulatorRunner robot(catalog().make("er1", {}, {}), emulators::PtyEndpoint{});
  FamilyRegistry registry;
  registry.add(er1_family());
  const ProbeResult result = probe_port(robot.device_path(), registry, {}, [] { return false; });
  ASSERT_TRUE(result.found) << result.problem;
  EXPECT_EQ(result.found->config_driver, "er1_position");
  EXPECT_EQ(result.baud, 230400);
  EXPECT_NE(result.found->model.find("ER1"), std::string::npos);
  EXPECT_NE(result.config_line.find("er1_position"), std::string::npos) << result.config_line;
}

}  // namespace
}  // namespace playerkit::families
