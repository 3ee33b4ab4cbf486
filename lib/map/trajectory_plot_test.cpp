#include "map/trajectory_plot.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <unistd.h>

#include <cstdlib>
#include <numbers>
#include <string>
#include <vector>

namespace playerkit::map {
namespace trajectory_plot_test {

using grid::CellState;
namespace fs = std::filesystem;

struct Rgb {
  int r, g, b;
};

class TrajectoryPlotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    folder_ = fs::temp_directory_path() /
              ("playerkit_plot_test_" + std::to_string(::getpid()) + "_" + info->name());
    fs::remove_all(folder_);
    fs::create_directories(folder_);
  }
  void TearDown() override { fs::remove_all(folder_); }

  cv::Mat plot(const grid::OccupancyGrid& grid, std::span<const PlotPath> paths,
               std::span<const Eigen::Vector2d> scan, const std::optional<geometry::Pose2>& pose,
               const PlotOptions& options) const {
    const fs::path file = folder_ / "plot.png";
    write_trajectory_plot(file, grid, paths, scan, pose, options);
    return cv::imread(file.string(), cv::IMREAD_COLOR);
  }

  fs::path folder_;
};

Rgb pixel(const cv::Mat& image, int column, int row) {
  const cv::Vec3b bgr = image.at<cv::Vec3b>(row, column);
  return {bgr[2], bgr[1], bgr[0]};
}

// Antialiasing may blend a little of the background into a line's centre.
::testing::AssertionResult near(const Rgb& actual, const Rgb& expected, int tolerance = 40) {
  if (std::abs(actual.r - expected.r) <= tolerance &&
      std::abs(actual.g - expected.g) <= tolerance &&
      std::abs(actual.b - expected.b) <= tolerance) {
    return ::testing::AssertionSuccess();
  }
  return ::testing::AssertionFailure()
         << "rgb(" << actual.r << ", " << actual.g << ", " << actual.b << ") is not near rgb("
         << expected.r << ", " << expected.g << ", " << expected.b << ")";
}

// 40 x 20 cells of 0.1 m from (1, 2): x in [1, 5), y in [2, 4). All free
// except an occupied wall in column 35 (x in [4.5, 4.6)). Without cropping at
// 400 px this is 10 px per cell, image row 0 at y = 4, so world (x, y) lands
// on drawing coordinate (100 (x - 1) - 0.5, 100 (4 - y) - 0.5); the points
// below sit on pixel centres.
grid::OccupancyGrid walled_room() {
  grid::OccupancyGrid room(40, 20, 0.1, {1.0, 2.0}, CellState::free);
  for (int row = 0; row < 20; ++row) room.set(35, row, CellState::occupied);
  return room;
}

TEST_F(TrajectoryPlotTest, DrawsMapPathsScanAndPoseWithWorldYUp) {
  const std::vector<PlotPath> paths{
      {{{1.5, 2.505}, {3.5, 2.505}}, {0, 0, 255}, "estimate"},  // row 149, columns 50..250
      {{{2.005, 2.2}, {2.005, 3.8}}, {0, 160, 0}, "truth"},     // column 100, rows 20..180
  };
  const std::vector<Eigen::Vector2d> scan{{4.055, 3.505}};         // pixel (305, 49)
  const geometry::Pose2 pose{2.505, 3.505, std::numbers::pi / 2};  // pixel (150, 49), pointing up

  const cv::Mat image =
      plot(walled_room(), paths, scan, pose, {.max_side_pixels = 400, .crop_to_content = false});
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 400);
  EXPECT_EQ(image.rows, 200);

  EXPECT_TRUE(near(pixel(image, 355, 145), {0, 0, 0}, 0));       // wall cell (35, 5)
  EXPECT_TRUE(near(pixel(image, 55, 145), {255, 255, 255}, 0));  // free cell (5, 5)
  EXPECT_TRUE(near(pixel(image, 180, 149), {0, 0, 255}));        // estimate, mid-segment
  EXPECT_TRUE(near(pixel(image, 100, 140), {0, 160, 0}));        // truth, y = 2.6
  EXPECT_TRUE(near(pixel(image, 305, 49), {255, 0, 0}));         // scan end point
  EXPECT_TRUE(near(pixel(image, 150, 42), {255, 140, 0}));       // arrow shaft, above the pose
  EXPECT_TRUE(near(pixel(image, 4, 4), {0, 0, 0}, 0));           // legend frame, top left
  // y is up: nothing is drawn where the scan point would land with y down.
  EXPECT_TRUE(near(pixel(image, 305, 150), {255, 255, 255}, 0));
}

TEST_F(TrajectoryPlotTest, SmallMapGrowsByWholePixelsPerCellLargeMapShrinksToMaxSide) {
  const PlotOptions whole_grid{.max_side_pixels = 100, .crop_to_content = false};
  cv::Mat image = plot(walled_room(), {}, {}, std::nullopt, whole_grid);
  EXPECT_EQ(image.cols, 80);  // 2 px per cell: 2.5 would blur cell edges
  EXPECT_EQ(image.rows, 40);
  EXPECT_TRUE(near(pixel(image, 71, 20), {0, 0, 0}, 0));  // wall column 35 -> pixels 70, 71

  image =
      plot(walled_room(), {}, {}, std::nullopt, {.max_side_pixels = 30, .crop_to_content = false});
  EXPECT_EQ(image.cols, 30);
  EXPECT_EQ(image.rows, 15);
}

TEST_F(TrajectoryPlotTest, CropsToKnownCellsPlusMargin) {
  // 100 x 100 unknown cells with a 20 x 10 known block at columns 40..59, rows 30..39.
  grid::OccupancyGrid grid(100, 100, 0.05, {0.0, 0.0});
  for (int row = 30; row < 40; ++row) {
    for (int col = 40; col < 60; ++col) grid.set(col, row, CellState::free);
  }
  grid.set(45, 32, CellState::occupied);

  // A 2-cell margin: 24 x 14 cells at 10 px each, cell (c, r) at pixel (10 (c - 38), 10 (41 - r)).
  const cv::Mat image =
      plot(grid, {}, {}, std::nullopt, {.max_side_pixels = 240, .crop_to_content = true});
  EXPECT_EQ(image.cols, 240);
  EXPECT_EQ(image.rows, 140);
  EXPECT_TRUE(near(pixel(image, 75, 95), {0, 0, 0}, 0));         // occupied cell (45, 32)
  EXPECT_TRUE(near(pixel(image, 125, 65), {255, 255, 255}, 0));  // free cell (50, 35)
  EXPECT_TRUE(near(pixel(image, 5, 5), {205, 205, 205}, 0));     // unknown margin
}

TEST_F(TrajectoryPlotTest, CropReachesPathsOutsideTheGridAndShowsThemOnGrey) {
  grid::OccupancyGrid grid(10, 10, 1.0, {0.0, 0.0}, CellState::free);
  const std::vector<PlotPath> paths{{{{5.0, 5.0}, {25.0, 5.0}}, {0, 0, 255}, ""}};
  const cv::Mat image =
      plot(grid, paths, {}, std::nullopt, {.max_side_pixels = 29, .crop_to_content = true});
  // Cells -2 .. 27 wide, -2 .. 12 high at 1 px each: pixel (c, r) shows cell (c - 2, 11 - r).
  EXPECT_EQ(image.cols, 29);
  EXPECT_EQ(image.rows, 14);
  EXPECT_TRUE(
      near(pixel(image, 20, 2), {205, 205, 205}, 0));  // cell (18, 9), beyond the grid: unknown
  EXPECT_TRUE(near(pixel(image, 5, 4), {255, 255, 255}, 0));  // cell (3, 7), free
}

TEST_F(TrajectoryPlotTest, UnwritableFileIsAMapFileError) {
  const fs::path file = folder_ / "no such folder" / "plot.png";
  EXPECT_THROW(write_trajectory_plot(file, walled_room(), {}, {}, std::nullopt), MapFileError);
}

TEST_F(TrajectoryPlotTest, EmptyGridIsRefused) {
  EXPECT_THROW(
      write_trajectory_plot(folder_ / "plot.png", grid::OccupancyGrid(), {}, {}, std::nullopt),
      std::invalid_argument);
}

}  // namespace trajectory_plot_test
}  // namespace playerkit::map
