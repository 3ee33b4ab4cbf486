#include "view/renderer.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace playerkit::view {
namespace renderer_test {

// 200 x 200 pixels over 2 m: 100 pixels a metre, the picture's centre at
// `centre`. No legend, so pixels near the top left are the map's.
constexpr Colour kWhite{255, 255, 255};

RenderOptions small() { return {.width = 200, .height = 200, .span = 2.0}; }

Frame empty_frame(Point centre) {
  Frame frame;
  frame.centre = centre;
  return frame;
}

bool is_grey(Colour colour, std::uint8_t level) {
  return colour.r == level && colour.g == level && colour.b == level;
}

// A 2 m x 2 m map at 0.1 m from (0, 0), free but for a wall in the cells
// from x = 1.2 to 1.3 m.
grid::OccupancyGrid walled_map() {
  grid::OccupancyGrid map(20, 20, 0.1, {0.0, 0.0}, grid::CellState::free);
  for (int row = 0; row < 20; ++row) map.set(12, row, grid::CellState::occupied);
  return map;
}

TEST(Renderer, DrawsTheMapsWallsWhereTheyAre) {
  const auto map = walled_map();
  const RgbImage image = render(empty_frame({1.0, 1.0}), &map, small());
  ASSERT_EQ(image.width, 200);
  ASSERT_EQ(image.height, 200);
  // x = 1.25 m lies 0.25 m right of the centre: column 125. y = 1.5 m is row 50.
  EXPECT_TRUE(is_grey(image.at(125, 50), 0));
  EXPECT_TRUE(is_grey(image.at(120, 50), 0));
  EXPECT_TRUE(is_grey(image.at(129, 50), 0));
  EXPECT_TRUE(is_grey(image.at(131, 50), 255));
  EXPECT_TRUE(is_grey(image.at(118, 50), 255));
}

TEST(Renderer, WallsShowThroughAreas) {
  const auto map = walled_map();
  Frame frame = empty_frame({1.0, 1.0});
  frame.areas.push_back({{{0.5, 0.5}, {1.8, 0.5}, {1.8, 1.5}, {0.5, 1.5}}, colours::kSonarCone});
  const RgbImage image = render(frame, &map, small());
  EXPECT_TRUE(is_grey(image.at(125, 100), 0));
  EXPECT_EQ(image.at(110, 100), colours::kSonarCone);
}

TEST(Renderer, OutsideTheMapIsUnknownGrey) {
  const auto map = walled_map();
  // Centred on the map's bottom-left corner: the left half lies at x < 0.
  const RgbImage image = render(empty_frame({0.0, 1.0}), &map, small());
  EXPECT_TRUE(is_grey(image.at(50, 60), 205));
  EXPECT_TRUE(is_grey(image.at(150, 60), 255));
}

TEST(Renderer, DrawsTheRobotAtItsPose) {
  Frame frame = empty_frame({0.0, 0.0});
  // Facing +y, 0.4 m long: the box reaches from row 80 to row 120, 30 wide.
  frame.bodies.push_back({{0.5, 0.0, 1.5707963267948966}, 0.4, 0.3, colours::kRobot, true});
  const RgbImage image = render(frame, nullptr, small());
  EXPECT_EQ(image.at(150 + 10, 100 + 15), colours::kRobot);
  EXPECT_EQ(image.at(150 - 10, 100 + 15), colours::kRobot);
  EXPECT_EQ(image.at(150, 100 - 25), kWhite);  // the heading line, inside the box
  EXPECT_NE(image.at(150 + 20, 100), colours::kRobot);          // beyond its width
  EXPECT_NE(image.at(150, 100 + 25), colours::kRobot);          // beyond its back
}

TEST(Renderer, DrawsAScansPoints) {
  Frame frame = empty_frame({0.0, 0.0});
  frame.dots.push_back({{{0.5, 0.5}, {-0.7, -0.2}}, colours::kLaserPoint, 2});
  const RgbImage image = render(frame, nullptr, small());
  EXPECT_EQ(image.at(150, 50), colours::kLaserPoint);
  EXPECT_EQ(image.at(30, 120), colours::kLaserPoint);
  EXPECT_NE(image.at(90, 90), colours::kLaserPoint);
}

TEST(Renderer, WritesLabelsBesideTheirPoint) {
  Frame frame = empty_frame({0.0, 0.0});
  frame.labels.push_back({{0.0, 0.0}, "42", colours::kFiducial});
  const RgbImage image = render(frame, nullptr, small());
  // The text starts 6 pixels right of (100, 100) and sits on the row 6 above.
  const auto teal = [&](int col, int row) {
    const Colour c = image.at(col, row);
    return c.g > c.r + 40 && c.b > c.r + 40;
  };
  int beside = 0, elsewhere = 0;
  for (int row = 0; row < 200; ++row) {
    for (int col = 0; col < 200; ++col) {
      if (!teal(col, row)) continue;
      (row >= 82 && row < 96 && col >= 104 && col < 125 ? beside : elsewhere) += 1;
    }
  }
  EXPECT_GT(beside, 15);
  EXPECT_EQ(elsewhere, 0);
}

TEST(Renderer, FillsAreas) {
  Frame frame = empty_frame({0.0, 0.0});
  frame.areas.push_back({{{0.0, 0.0}, {0.8, 0.0}, {0.8, 0.8}}, colours::kLaserFan});
  const RgbImage image = render(frame, nullptr, small());
  EXPECT_EQ(image.at(170, 60), colours::kLaserFan);  // (0.7, 0.4): inside the triangle
  EXPECT_NE(image.at(120, 40), colours::kLaserFan);  // (0.2, 0.6): above its diagonal
}

TEST(Renderer, WritesTheLegendTopLeftAndAScaleBarBottomLeft) {
  Frame frame = empty_frame({0.0, 0.0});
  frame.legend.push_back({"laser:0 5.0 Hz", colours::kText});
  const RgbImage image = render(frame, nullptr, {.width = 400, .height = 300, .span = 10.0});
  int dark_top_left = 0, dark_bottom_left = 0;
  for (int row = 0; row < 25; ++row) {
    for (int col = 0; col < 120; ++col) dark_top_left += image.at(col, row).r < 100;
  }
  for (int row = 280; row < 300; ++row) {
    for (int col = 0; col < 120; ++col) dark_bottom_left += image.at(col, row).r < 100;
  }
  EXPECT_GT(dark_top_left, 50);
  EXPECT_GT(dark_bottom_left, 50);
}

TEST(Renderer, RefusesSizesItCannotDraw) {
  EXPECT_THROW(render(empty_frame({}), nullptr, {.width = 8, .height = 100, .span = 1.0}), std::invalid_argument);
  EXPECT_THROW(render(empty_frame({}), nullptr, {.width = 100, .height = 100, .span = 0.0}), std::invalid_argument);
}

TEST(Renderer, WritesAPng) {
  const auto path = std::filesystem::path(testing::TempDir()) / "renderer_test.png";
  write_png(path, render(empty_frame({}), nullptr, small()));
  std::ifstream in(path, std::ios::binary);
  char signature[8] = {};
  in.read(signature, 8);
  EXPECT_EQ(std::string(signature + 1, 3), "PNG");
  std::filesystem::remove(path);
}

}  // namespace renderer_test
}  // namespace playerkit::view
