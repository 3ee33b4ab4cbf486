// Worlds loaded all the way into sim::World: ids, devices and a laser scan
// that sees the bitmap where an independent ray march on its pixels does.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "sim/worldfile/world_loader.hpp"
#include "sim/worldfile/world_loader_test_support.hpp"

namespace playerkit::sim::worldfile {
namespace world_loader_make_test {

using namespace loader_test_support;

const SimDevice& loaded_device(const LoadedWorld& world, std::uint16_t port, std::uint16_t code, std::uint16_t index) {
  for (const SimDevice& found : world.devices) {
    if (found.port == port && found.interface_code == code && found.index == index) return found;
  }
  throw std::runtime_error("no such device");
}

TEST(WorldLoaderMake, DevicesNameTheWorldsModels) {
  const LoadedWorld loaded = load_world(worlds_dir() / "example-13.world");
  const WorldDescription described = describe_world(worlds_dir() / "example-13.world");
  EXPECT_EQ(loaded.world.size(), described.models.size());
  EXPECT_EQ(loaded.devices.size(), 10u);
  const ModelId robot1 = loaded_device(loaded, 6665, 4, 0).model;
  EXPECT_EQ(loaded.world.find("robot1"), robot1);
  EXPECT_EQ(loaded.world.spec(robot1).type, "position");
  const ModelId truth2 = loaded_device(loaded, 6666, 15, 0).model;
  EXPECT_EQ(loaded.world.spec(truth2).parent, loaded.world.find("robot2"));
  const geometry::Pose2 start = loaded.world.true_pose(robot1);
  EXPECT_NEAR(start.x, 2.0, 1e-12);
  EXPECT_NEAR(start.yaw, 45 * kDeg, 1e-12);
  for (const SimDevice& device : loaded.devices) {
    EXPECT_EQ(loaded.world.spec(device.model).type, device.driver_name) << device.driver_name;
  }
}

TEST(WorldLoaderMake, SimpleWorldsLaserSeesTheCaveWalls) {
  LoadedWorld loaded = load_world(worlds_dir() / "simple.world", {.seed = 1, .default_port = 6665});
  World& world = loaded.world;
  const ModelId laser = loaded_device(loaded, 6665, 6, 0).model;
  world.set_active(laser, true);
  for (int i = 0; i < 3; ++i) world.step();
  const LaserScan& scan = world.laser(laser);
  ASSERT_EQ(scan.ranges.size(), 361u);

  // cave.pnm read here: pixel (c, r) covers x in [c, c+1] 0.03, y in [499 - r, 500 - r] 0.03.
  std::ifstream in(worlds_dir() / "cave.pnm", std::ios::binary);
  std::string line;
  std::getline(in, line);  // P5
  do std::getline(in, line);
  while (line.starts_with("#"));  // comment, then "500 500"
  std::getline(in, line);  // 255
  std::vector<unsigned char> pixels(500 * 500);
  in.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
  // Stage 1.3 closes the world with a wall one cell inside its border
  // (cells 1 and 498 here): the cave's bitmap is open at the image's edge.
  const auto wall_at = [&](double x, double y) {
    const int col = static_cast<int>(std::floor(x / 0.03)), up = static_cast<int>(std::floor(y / 0.03));
    const int row = 499 - up;
    if (col <= 1 || up <= 1 || col >= 498 || up >= 498) return true;
    return pixels[static_cast<std::size_t>(row * 500 + col)] != 0;
  };
  const geometry::Pose2 origin = world.true_pose(laser);
  int compared = 0;
  for (std::size_t beam = 0; beam < scan.ranges.size(); beam += 20) {
    const double bearing = origin.yaw - std::numbers::pi / 2 + std::numbers::pi * static_cast<double>(beam) / 360.0;
    double range = 0.0;
    while (range < 8.0 && !wall_at(origin.x + range * std::cos(bearing), origin.y + range * std::sin(bearing))) {
      range += 0.001;
    }
    if (range >= 8.0) continue;
    EXPECT_NEAR(scan.ranges[beam], range, 0.03 * std::sqrt(2.0) + 0.001) << "beam " << beam;
    ++compared;
  }
  EXPECT_GT(compared, 10);
}

}  // namespace world_loader_make_test
}  // namespace playerkit::sim::worldfile
