#include "sim/render/world_png.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <fstream>
#include <iterator>
#include <string>

#include "files/output_file.hpp"
#include "files/same_file.hpp"
#include "sim/world/world_test_support.hpp"
#include "support/scratch_directory.hpp"

namespace playerkit::sim::render {
namespace world_png_test {

using world_test_support::model;

World small_world() {
  auto map = grid::OccupancyGrid::centred(60, 40, 0.05, grid::CellState::free);  // 3 x 2 m
  for (int col = 0; col < 60; ++col) map.set(col, 0, grid::CellState::occupied);
  World world({.step = 0.1, .seed = 0}, map);
  ModelSpec robot = model("robot", kNoModel, {0.5, 0.2, 1.0}, PositionSpec{});
  robot.color = {0, 200, 0};
  world.add(robot);
  return world;
}

std::string contents(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(WorldPng, APngOpenCvReadsBackPixelForPixel) {
  const testing::ScratchDirectory scratch("world_png_test");
  const World world = small_world();
  const Picture picture = draw_world(take_snapshot(world));
  const auto file = scratch.file("world.png");
  write_png(file, picture);
  EXPECT_EQ(contents(file).substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  const cv::Mat read = cv::imread(file.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(read.empty());
  EXPECT_EQ(read.cols, 1600);  // 3 m long at 1600 px
  EXPECT_EQ(read.rows, 1067);  // 2 m at 533.3 px/m, rounded up
  int different = 0;
  for (int row = 0; row < read.rows; ++row) {
    for (int col = 0; col < read.cols; ++col) {
      const cv::Vec3b bgr = read.at<cv::Vec3b>(row, col);
      const Rgb expected = picture.at(col, row);
      if (bgr[2] != expected.r || bgr[1] != expected.g || bgr[0] != expected.b) ++different;
    }
  }
  EXPECT_EQ(different, 0);
}

TEST(WorldPng, WriteWorldPngDrawsTheWorldAtTheAskedSize) {
  const testing::ScratchDirectory scratch("world_png_test");
  const World world = small_world();
  const auto file = scratch.file("small.png");
  write_world_png(file, world, nullptr, {.max_side_pixels = 300});
  const cv::Mat read = cv::imread(file.string(), cv::IMREAD_COLOR);
  ASSERT_EQ(read.cols, 300);
  ASSERT_EQ(read.rows, 200);
  // 0.1 m behind the robot's centre (0.5, 0.2), heading 1 rad: (0.446, 0.116), at
  // 100 px/m from the map's corner (-1.5, 1.0) pixel (194, 88), in green.
  const cv::Vec3b behind = read.at<cv::Vec3b>(88, 194);
  EXPECT_EQ(behind, cv::Vec3b(0, 200, 0));
  // The heading line runs from the centre, pixel (200, 80), in black.
  EXPECT_EQ(read.at<cv::Vec3b>(80, 200), cv::Vec3b(0, 0, 0));
  // The wall along the bottom row of cells.
  const cv::Vec3b wall = read.at<cv::Vec3b>(199, 150);
  EXPECT_LT(wall[0] + wall[1] + wall[2], 3 * 64);
}

TEST(WorldPng, NeverWritesOverAnInputAndKeepsThePreviousFileOnFailure) {
  const testing::ScratchDirectory scratch("world_png_test");
  const World world = small_world();
  const auto input = scratch.write("world.world", "resolution 0.05\n");
  EXPECT_THROW(write_world_png(input, world, nullptr, {}, {input}), files::OutputIsInputError);
  EXPECT_EQ(contents(input), "resolution 0.05\n");
  EXPECT_THROW(write_world_png(scratch.file("missing/world.png"), world), files::OutputError);
}

}  // namespace world_png_test
}  // namespace playerkit::sim::render
