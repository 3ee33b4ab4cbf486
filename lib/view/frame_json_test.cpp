#include "view/frame_json.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

namespace playerkit::view {
namespace frame_json_test {

TEST(FrameJson, CarriesEveryShapeWithFlatPointsInMillimetres) {
  Frame frame;
  frame.centre = {1.23456, -2.0};
  frame.areas.push_back({{{0, 0}, {1, 0}, {1, 1}}, colours::kLaserFan});
  frame.dots.push_back({{{0.5, 0.25}}, colours::kLaserPoint, 2});
  frame.ellipses.push_back({{1, 2}, 0.4, 0.2, 0.5, colours::kHypothesis});
  frame.bodies.push_back({{2, 2, 0.785398}, 0.44, 0.38, colours::kRobot, true});
  frame.legend.push_back({"laser:0 5.0 Hz", colours::kText});
  frame.labels.push_back({{1.0, 2.0}, "7", colours::kFiducial});
  const auto json = nlohmann::json::parse(frame_json(frame));
  EXPECT_EQ(json["type"], "frame");
  EXPECT_EQ(json["centre"], nlohmann::json::parse("[1.235, -2.0]"));
  EXPECT_EQ(json["areas"][0]["fill"], "#c8e1ff");
  EXPECT_EQ(json["areas"][0]["points"], nlohmann::json::parse("[0, 0, 1, 0, 1, 1]"));
  EXPECT_EQ(json["dots"][0]["radius"], 2);
  EXPECT_EQ(json["dots"][0]["points"], nlohmann::json::parse("[0.5, 0.25]"));
  EXPECT_EQ(json["ellipses"][0]["a"], 0.4);
  EXPECT_EQ(json["bodies"][0]["pose"], nlohmann::json::parse("[2, 2, 0.785]"));
  EXPECT_EQ(json["bodies"][0]["filled"], true);
  EXPECT_EQ(json["legend"][0]["text"], "laser:0 5.0 Hz");
  EXPECT_TRUE(json["lines"].empty());
  EXPECT_EQ(json["labels"][0]["text"], "7");
  EXPECT_EQ(json["labels"][0]["at"], nlohmann::json::parse("[1.0, 2.0]"));
}

TEST(FrameJson, TheMapIsOneByteACellInBase64) {
  grid::OccupancyGrid map(2, 2, 0.5, {-1.0, 0.0}, grid::CellState::free);
  map.set(1, 0, grid::CellState::occupied);
  map.set(0, 1, grid::CellState::unknown);
  const auto json = nlohmann::json::parse(map_json(map));
  EXPECT_EQ(json["type"], "map");
  EXPECT_EQ(json["width"], 2);
  EXPECT_EQ(json["resolution"], 0.5);
  EXPECT_EQ(json["origin"], nlohmann::json::parse("[-1.0, 0.0]"));
  EXPECT_EQ(json["cells"], "AAIBAA==");  // bytes 0, 2, 1, 0
}

}  // namespace frame_json_test
}  // namespace playerkit::view
