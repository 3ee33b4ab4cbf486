// The example worlds of data/worlds load with the models, poses, ports and
// devices their files describe (stage-worlds.md §5).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>

#include "map/map_file.hpp"
#include "sim/worldfile/world_loader.hpp"
#include "sim/worldfile/world_loader_test_support.hpp"

namespace playerkit::sim::worldfile {
namespace world_loader_examples_test {

using namespace loader_test_support;

// The pixels of a binary PGM, row 0 at the top, read here independently of
// lib/map.
struct Pgm {
  int width = 0, height = 0;
  std::vector<unsigned char> pixels;
  [[nodiscard]] int at(int col, int row) const { return pixels[static_cast<std::size_t>(row * width + col)]; }
};

Pgm read_pgm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string magic;
  in >> magic;
  EXPECT_EQ(magic, "P5");
  Pgm pgm;
  int maxval = 0;
  const auto skip_comments = [&] {
    in >> std::ws;
    while (in.peek() == '#') {
      std::string comment;
      std::getline(in, comment);
      in >> std::ws;
    }
  };
  skip_comments();
  in >> pgm.width;
  skip_comments();
  in >> pgm.height;
  skip_comments();
  in >> maxval;
  in.get();
  pgm.pixels.resize(static_cast<std::size_t>(pgm.width * pgm.height));
  in.read(reinterpret_cast<char*>(pgm.pixels.data()), static_cast<std::streamsize>(pgm.pixels.size()));
  return pgm;
}

TEST(WorldLoaderExamples, Example13HasTwoRobotsOnTheirPorts) {
  const WorldDescription world = describe_world(worlds_dir() / "example-13.world");
  EXPECT_EQ(world.dialect, Dialect::stage13);
  EXPECT_DOUBLE_EQ(world.settings.step, 0.1);
  EXPECT_EQ(device_list(world), (std::vector<std::string>{
                                    "6665:4:0 position", "6665:5:0 sonar", "6665:6:0 laser", "6665:10:0 fiducialfinder",
                                    "6665:8:0 ptz", "6665:7:0 blobfinder", "6665:15:0 truth", "6666:4:0 position",
                                    "6666:6:0 laser", "6666:15:0 truth"}));

  const ModelSpec& robot1 = model_named(world, "robot1");
  EXPECT_EQ(robot1.type, "position");
  EXPECT_EQ(robot1.port, 6665);
  EXPECT_NEAR(robot1.pose.x, 2.0, 1e-12);
  EXPECT_NEAR(robot1.pose.y, 2.0, 1e-12);
  EXPECT_NEAR(robot1.pose.yaw, 45 * kDeg, 1e-12);
  EXPECT_NEAR(robot1.body.size.x(), 0.44, 1e-12);
  EXPECT_NEAR(robot1.body.size.y(), 0.38, 1e-12);
  EXPECT_NEAR(robot1.body.offset.x, -0.04, 1e-12);
  const auto& position = std::get<PositionSpec>(robot1.params);
  EXPECT_TRUE(std::isinf(position.max_velocity.x()));  // 1.3 has no velocity limits
  EXPECT_EQ(position.localization, Localization::odometry);

  const ModelSpec& sonar = world.models.at(device(world, 6665, 5, 0).model);
  const auto& ring = std::get<SonarSpec>(sonar.params);
  ASSERT_EQ(ring.transducers.size(), 8u);
  EXPECT_NEAR(ring.transducers[1].x, 0.155, 1e-12);
  EXPECT_NEAR(ring.transducers[1].y, 0.115, 1e-12);
  EXPECT_NEAR(ring.transducers[1].yaw, 50 * kDeg, 1e-12);
  EXPECT_NEAR(ring.transducers[7].yaw, -90 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(ring.range_max, 5.0);
  EXPECT_EQ(world.models.at(static_cast<std::size_t>(sonar.parent)).name, "robot1");

  const auto& laser = std::get<LaserSpec>(world.models.at(device(world, 6665, 6, 0).model).params);
  EXPECT_EQ(laser.samples, 361);
  EXPECT_NEAR(laser.fov, 180 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(laser.range_max, 8.0);
  const ModelSpec& finder = world.models.at(device(world, 6665, 10, 0).model);
  EXPECT_EQ(world.models.at(static_cast<std::size_t>(finder.parent)).type, "laser");
  EXPECT_DOUBLE_EQ(std::get<FiducialSpec>(finder.params).range_max, 6.0);
  EXPECT_DOUBLE_EQ(std::get<FiducialSpec>(finder.params).range_max_id, 3.0);
  EXPECT_NEAR(std::get<PtzSpec>(world.models.at(device(world, 6665, 8, 0).model).params).max_fov, 120 * kDeg, 1e-12);
  const auto& blobs = std::get<BlobfinderSpec>(world.models.at(device(world, 6665, 7, 0).model).params);
  EXPECT_EQ(blobs.channels, (std::vector<Rgb>{{255, 0, 0}, {0, 255, 0}}));
  EXPECT_NEAR(blobs.fov, 120 * kDeg, 1e-12);  // the wide ptz's

  // robot2 has no truth in the file; it gets one anyway.
  const SimDevice& truth2 = device(world, 6666, 15, 0);
  EXPECT_EQ(world.models.at(static_cast<std::size_t>(world.models.at(truth2.model).parent)).name, "robot2");
  EXPECT_TRUE(std::holds_alternative<TruthSpec>(world.models.at(truth2.model).params));

  // The beacon (a box macro) and the green box are models, not devices.
  const auto beacon = std::find_if(world.models.begin(), world.models.end(),
                                   [](const ModelSpec& model) { return model.returns.fiducial_id == 5; });
  ASSERT_NE(beacon, world.models.end());
  EXPECT_EQ(beacon->type, "box");
  EXPECT_EQ(beacon->body.shape, Shape::circle);
  EXPECT_NEAR(beacon->body.size.x(), 0.2, 1e-12);
  EXPECT_EQ(beacon->color, (Rgb{255, 0, 0}));
  EXPECT_TRUE(beacon->returns.laser_bright);
  EXPECT_NEAR(beacon->pose.y, 3.5, 1e-12);
  const auto box = std::find_if(world.models.begin(), world.models.end(), [](const ModelSpec& model) {
    return model.type == "box" && model.returns.fiducial_id == 0;
  });
  ASSERT_NE(box, world.models.end());
  EXPECT_EQ(box->color, (Rgb{0, 255, 0}));
  EXPECT_TRUE(world.warnings.empty()) << world.warnings.front();
}

TEST(WorldLoaderExamples, Example13MapIsCavePixelForPixelAndClosed) {
  const WorldDescription world = describe_world(worlds_dir() / "example-13.world");
  const Pgm cave = read_pgm(worlds_dir() / "cave.pnm");
  const grid::OccupancyGrid& map = world.map;
  ASSERT_EQ(map.width(), 500);
  ASSERT_EQ(map.height(), 500);
  EXPECT_DOUBLE_EQ(map.resolution(), 0.03);
  EXPECT_EQ(map.origin(), Eigen::Vector2d::Zero());
  int walls = 0, mismatches = 0;
  for (int row = 0; row < cave.height; ++row) {
    for (int col = 0; col < cave.width; ++col) {
      // Bottom-left corner at (0, 0): pixel (c, r) covers x in [c, c+1] * 0.03, y in [499 - r, 500 - r] * 0.03.
      const Eigen::Vector2d centre((col + 0.5) * 0.03, (cave.height - 1 - row + 0.5) * 0.03);
      const int grid_col = col, grid_row = cave.height - 1 - row;
      const bool border = grid_col == 1 || grid_col == 498 || grid_row == 1 || grid_row == 498;
      const bool inside_border = grid_col >= 1 && grid_col <= 498 && grid_row >= 1 && grid_row <= 498;
      const bool wall = cave.at(col, row) != 0 || (border && inside_border);
      walls += cave.at(col, row) != 0;
      if ((map.state_at_world(centre) == grid::CellState::occupied) != wall) ++mismatches;
    }
  }
  EXPECT_EQ(walls, 5269);
  EXPECT_EQ(mismatches, 0);
  // Outside the closing wall the outermost ring stays free.
  EXPECT_EQ(map.at(0, 250), grid::CellState::free);
  EXPECT_EQ(map.at(1, 250), grid::CellState::occupied);
}

TEST(WorldLoaderExamples, Example4aIsStage4WithSonarFirstThenLaser) {
  const WorldDescription world = describe_world(worlds_dir() / "example-4a.world", {.seed = 3, .default_port = 7000});
  EXPECT_EQ(world.dialect, Dialect::stage4);
  EXPECT_DOUBLE_EQ(world.settings.step, 0.1);
  EXPECT_EQ(world.settings.seed, 3u);
  EXPECT_EQ(device_list(world), (std::vector<std::string>{"7000:4:0 position", "7000:5:0 ranger", "7000:6:0 ranger",
                                                          "7000:15:0 truth", "7000:4:1 position", "7000:5:1 ranger",
                                                          "7000:15:1 truth"}));
  const ModelSpec& r0 = model_named(world, "r0");
  EXPECT_NEAR(r0.pose.x, -6.5, 1e-12);
  EXPECT_NEAR(r0.pose.y, -6.0, 1e-12);
  EXPECT_NEAR(r0.pose.yaw, 45 * kDeg, 1e-12);
  EXPECT_NEAR(r0.body.offset.x, -0.04, 1e-12);
  EXPECT_EQ(r0.color, (Rgb{255, 0, 0}));
  EXPECT_DOUBLE_EQ(r0.returns.ranger, 0.5);
  EXPECT_EQ(r0.returns.fiducial_id, 1);
  const auto& drive = std::get<PositionSpec>(r0.params);
  EXPECT_EQ(drive.localization, Localization::gps);
  EXPECT_NEAR(drive.max_velocity.x(), 0.5, 1e-12);
  EXPECT_NEAR(drive.min_velocity.y(), 0.0, 1e-12);
  EXPECT_NEAR(drive.max_velocity.z(), 90 * kDeg, 1e-12);

  const ModelSpec& sonar = world.models.at(device(world, 7000, 5, 0).model);
  EXPECT_EQ(sonar.name, "r0.ranger:0");
  EXPECT_FALSE(sonar.body.present);
  const auto& ring = std::get<SonarSpec>(sonar.params);
  ASSERT_EQ(ring.transducers.size(), 8u);
  EXPECT_NEAR(ring.transducers[0].x, 0.075, 1e-12);
  EXPECT_NEAR(ring.transducers[0].yaw, 90 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(ring.range_max, 5.0);
  const ModelSpec& lms200 = world.models.at(device(world, 7000, 6, 0).model);
  EXPECT_EQ(lms200.name, "r0.ranger:1");
  EXPECT_TRUE(lms200.body.present);  // its block
  EXPECT_EQ(lms200.color, (Rgb{0, 0, 255}));
  const auto& laser = std::get<LaserSpec>(lms200.params);
  EXPECT_EQ(laser.samples, 180);
  EXPECT_NEAR(laser.fov, 180 * kDeg, 1e-12);
  EXPECT_DOUBLE_EQ(laser.range_max, 8.0);
  EXPECT_EQ(model_named(world, "r1").color, (Rgb{0, 0, 255}));
  EXPECT_FALSE(model_named(world, "cave").body.present);  // its walls are the map's
  EXPECT_TRUE(world.warnings.empty()) << world.warnings.front();
}

// stage-cave.png's dark pixels reach every edge: the 500 x 500 image is
// stretched to 16 x 16 m centred on (0, 0), 0.032 m per pixel, coarser than
// the world's 0.02 m resolution, so the map's cells are the pixels.
TEST(WorldLoaderExamples, Example4aMapIsTheStretchedCave) {
  const WorldDescription world = describe_world(worlds_dir() / "example-4a.world");
  EXPECT_DOUBLE_EQ(world.map.resolution(), 0.032);
  const grid::OccupancyGrid pixels =
      map::load_map(worlds_dir() / "stage-cave.png", {.resolution = 1.0, .negate = false, .occupied_threshold = 0.5,
                                                      .free_threshold = 0.0});
  ASSERT_EQ(pixels.width(), 500);
  const auto dark = [&](int col, int row) {  // row 0 at the bottom
    return pixels.contains(col, row) && pixels.at(col, row) == grid::CellState::occupied;
  };
  // One cell per pixel: a cell is occupied exactly where its pixel is dark
  // or holds the floorplan's 0.01 m boundary walls (the edge pixels).
  int walls = 0, mismatches = 0;
  for (int row = 0; row < 500; ++row) {
    for (int col = 0; col < 500; ++col) {
      const Eigen::Vector2d centre((col + 0.5 - 250.0) * 0.032, (row + 0.5 - 250.0) * 0.032);
      const bool edge = col == 0 || row == 0 || col == 499 || row == 499;
      const bool wall = dark(col, row) || edge;
      walls += wall;
      if ((world.map.state_at_world(centre) == grid::CellState::occupied) != wall) ++mismatches;
    }
  }
  EXPECT_EQ(mismatches, 0);
  EXPECT_GT(walls, 5000);
  int occupied = 0;
  for (const grid::CellState state : world.map.cells()) occupied += state == grid::CellState::occupied;
  EXPECT_EQ(occupied, walls);  // nothing outside the image
  // `boundary 1`: 0.01 m walls just inside [-8, 8], whatever the pixels there.
  for (double along = -7.99; along < 8.0; along += 0.1) {
    EXPECT_EQ(world.map.state_at_world({-7.995, along}), grid::CellState::occupied) << along;
    EXPECT_EQ(world.map.state_at_world({along, 7.995}), grid::CellState::occupied) << along;
  }
  EXPECT_EQ(world.map.state_at_world({-8.01, 0.0}), grid::CellState::free);
  // The robots start on open floor.
  EXPECT_EQ(world.map.state_at_world({-6.5, -6.0}), grid::CellState::free);
  EXPECT_EQ(world.map.state_at_world({-4.0, -5.0}), grid::CellState::free);
}

TEST(WorldLoaderExamples, Example4bScoutsHaveLaserFiducialBlobfinderGripper) {
  const WorldDescription world = describe_world(worlds_dir() / "example-4b.world");
  EXPECT_EQ(world.dialect, Dialect::stage4);
  EXPECT_EQ(device_list(world),
            (std::vector<std::string>{"6665:4:0 position", "6665:6:0 ranger", "6665:10:0 fiducial",
                                      "6665:7:0 blobfinder", "6665:3:0 gripper", "6665:15:0 truth",
                                      "6665:4:1 position", "6665:6:1 ranger", "6665:10:1 fiducial",
                                      "6665:7:1 blobfinder", "6665:3:1 gripper", "6665:15:1 truth"}));
  const ModelSpec& s1 = model_named(world, "s1");
  const auto& odometry = std::get<PositionSpec>(s1.params);
  EXPECT_EQ(odometry.localization, Localization::odometry);
  ASSERT_TRUE(odometry.odom_error.has_value());
  EXPECT_NEAR(odometry.odom_error->x(), 0.03, 1e-12);
  EXPECT_NEAR(odometry.odom_error->z(), 0.05, 1e-12);
  EXPECT_NEAR(odometry.max_velocity.z(), 60 * kDeg, 1e-12);
  EXPECT_EQ(s1.returns.fiducial_id, 17);
  EXPECT_EQ(model_named(world, "s2").returns.fiducial_id, 18);
  EXPECT_EQ(model_named(world, "s2").color, (Rgb{0, 255, 0}));
  EXPECT_NEAR(model_named(world, "s2").pose.yaw, 180 * kDeg, 1e-12);

  const ModelSpec& ranger = world.models.at(device(world, 6665, 6, 1).model);
  EXPECT_EQ(ranger.name, "s2.ranger:0");
  const auto& laser = std::get<LaserSpec>(ranger.params);
  EXPECT_EQ(laser.samples, 121);
  EXPECT_NEAR(laser.fov, 240 * kDeg, 1e-12);
  EXPECT_NEAR(laser.pose.x, 0.1, 1e-12);
  EXPECT_DOUBLE_EQ(laser.range_max, 6.0);
  const auto& fiducial = std::get<FiducialSpec>(world.models.at(device(world, 6665, 10, 0).model).params);
  EXPECT_DOUBLE_EQ(fiducial.range_max, 6.0);
  EXPECT_DOUBLE_EQ(fiducial.range_max_id, 3.0);
  EXPECT_NEAR(fiducial.fov, 120 * kDeg, 1e-12);
  const auto& blobs = std::get<BlobfinderSpec>(world.models.at(device(world, 6665, 7, 0).model).params);
  EXPECT_EQ(blobs.channels, (std::vector<Rgb>{{255, 0, 0}, {0, 255, 0}}));
  EXPECT_EQ(blobs.image_width, 80);
  EXPECT_DOUBLE_EQ(blobs.range, 6.0);
  const ModelSpec& gripper = world.models.at(device(world, 6665, 3, 0).model);
  EXPECT_EQ(gripper.color, (Rgb{190, 190, 190}));  // X11 "gray"
  EXPECT_NEAR(gripper.pose.x, 0.22, 1e-12);

  int pucks = 0;
  for (const ModelSpec& model : world.models) {
    if (!model.returns.gripper) continue;
    ++pucks;
    EXPECT_EQ(model.type, "model");
    EXPECT_NEAR(model.body.size.x(), 0.08, 1e-12);
    EXPECT_EQ(model.color, (Rgb{255, 0, 0}));
  }
  EXPECT_EQ(pucks, 2);
  EXPECT_EQ(world.models.at(world.models.size() - 1).returns.fiducial_id, 11);
  EXPECT_TRUE(world.warnings.empty()) << world.warnings.front();
}

// stage-autolab.png: only the dark pixels' bounding box is stretched to
// 20 x 20 m (Stage's rule), not the whole 809 x 689 image.
TEST(WorldLoaderExamples, Example4bStretchesTheDarkBoundingBox) {
  const WorldDescription world = describe_world(worlds_dir() / "example-4b.world");
  const grid::OccupancyGrid pixels = map::load_map(
      worlds_dir() / "stage-autolab.png", {.resolution = 1.0, .negate = false, .occupied_threshold = 0.5,
                                           .free_threshold = 0.0});
  int first_col = pixels.width(), last_col = -1, first_row = pixels.height(), last_row = -1;
  for (int row = 0; row < pixels.height(); ++row) {
    for (int col = 0; col < pixels.width(); ++col) {
      if (pixels.at(col, row) != grid::CellState::occupied) continue;
      first_col = std::min(first_col, col), last_col = std::max(last_col, col);
      first_row = std::min(first_row, row), last_row = std::max(last_row, row);
    }
  }
  // The fact sheet's figures: columns 2-806 and rows 2-686 of the image.
  EXPECT_EQ(first_col, 2);
  EXPECT_EQ(last_col, 806);
  EXPECT_EQ(last_row - first_row + 1, 685);
  const double sx = 20.0 / 805.0, sy = 20.0 / 685.0;
  const double centre_col = (first_col + last_col + 1) / 2.0, centre_row = (first_row + last_row + 1) / 2.0;
  int checked = 0;
  for (int row = first_row; row <= last_row; row += 2) {
    for (int col = first_col; col <= last_col; col += 2) {
      if (pixels.at(col, row) != grid::CellState::occupied) continue;
      const Eigen::Vector2d centre((col + 0.5 - centre_col) * sx, (row + 0.5 - centre_row) * sy);
      EXPECT_EQ(world.map.state_at_world(centre), grid::CellState::occupied) << col << "," << row;
      ++checked;
    }
  }
  EXPECT_GT(checked, 500);
  // The walls span exactly [-10, 10] in both axes.
  EXPECT_EQ(world.map.state_at_world({-9.999, 0.0}), grid::CellState::occupied);
  EXPECT_EQ(world.map.state_at_world({-10.01, 0.0}), grid::CellState::free);
  for (const char* name : {"s1", "s2"}) {
    const ModelSpec& scout = model_named(world, name);
    EXPECT_EQ(world.map.state_at_world(scout.pose.translation()), grid::CellState::free) << name;
  }
}

TEST(WorldLoaderExamples, SimpleWorldServesOneRobotOnTheDefaultPort) {
  const WorldDescription world = describe_world(worlds_dir() / "simple.world", {.default_port = 7123});
  EXPECT_EQ(world.dialect, Dialect::stage13);
  EXPECT_EQ(device_list(world), (std::vector<std::string>{"7123:4:0 position", "7123:5:0 sonar", "7123:6:0 laser",
                                                          "7123:15:0 truth"}));
  const ModelSpec& robot = model_named(world, "robot");
  const auto& ring = std::get<SonarSpec>(world.models.at(device(world, 7123, 5, 0).model).params);
  EXPECT_EQ(ring.transducers.size(), 16u);
  EXPECT_NEAR(ring.transducers[12].yaw, 170 * kDeg, 1e-12);
  EXPECT_EQ(std::get<LaserSpec>(world.models.at(device(world, 7123, 6, 0).model).params).samples, 361);
  // Open floor within 0.35 m of the robot.
  for (double dx = -0.35; dx <= 0.35; dx += 0.01) {
    for (double dy = -0.35; dy <= 0.35; dy += 0.01) {
      if (dx * dx + dy * dy > 0.35 * 0.35) continue;
      ASSERT_EQ(world.map.state_at_world(robot.pose.translation() + Eigen::Vector2d(dx, dy)), grid::CellState::free);
    }
  }
  EXPECT_TRUE(world.warnings.empty()) << world.warnings.front();
}

}  // namespace world_loader_examples_test
}  // namespace playerkit::sim::worldfile
