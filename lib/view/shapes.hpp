#pragma once
// What a view draws, in world metres (x right, y up): the Scene makes a
// Frame from the messages it was given, the PNG renderer and (later) the
// live page draw the same Frame, so both follow one set of layout rules.
// Plain data, no drawing library.

#include <cstdint>
#include <string>
#include <vector>

#include "client/typed/pose.hpp"

namespace playerkit::view {

struct Colour {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Colour&, const Colour&) = default;
};

struct Point {
  double x = 0, y = 0;
  friend bool operator==(const Point&, const Point&) = default;
};

// Filled areas, drawn first: a laser's free-space fan, sonar and IR cones.
struct Area {
  std::vector<Point> points;
  Colour fill;
};

// An odometry trail.
struct Line {
  std::vector<Point> points;
  Colour colour;
};

// Laser returns; sizes are pixels, so points stay visible at any zoom.
struct Dots {
  std::vector<Point> points;
  Colour colour;
  int radius_pixels = 1;
};

// A localize hypothesis: the covariance's ellipse, axes in metres.
struct Ellipse {
  Point centre;
  double semi_major = 0, semi_minor = 0;
  double angle = 0;  // rad, of the major axis
  Colour colour;
};

// The robot (filled), its true pose or a fiducial (outlines): a box with a
// heading line.
struct Body {
  client::Pose2D pose;
  double length = 0, width = 0;  // m
  Colour colour;
  bool filled = true;
};

// A fiducial's id beside it; the size is the font's, in pixels.
struct Label {
  Point at;
  std::string text;
  Colour colour;
};

struct LegendEntry {
  std::string text;  // "laser:0 5.0 Hz"
  Colour colour;
};

struct Frame {
  Point centre;  // where the view looks: the robot
  std::vector<Area> areas;
  std::vector<Line> lines;
  std::vector<Dots> dots;
  std::vector<Ellipse> ellipses;
  std::vector<Body> bodies;
  std::vector<Label> labels;
  std::vector<LegendEntry> legend;
};

// The palette, shared by every drawing of a Frame.
namespace colours {
inline constexpr Colour kLaserFan{200, 225, 255};
inline constexpr Colour kLaserPoint{0, 60, 220};
inline constexpr Colour kLaserBright{255, 140, 0};  // returns with a non-zero intensity
inline constexpr Colour kSonarCone{190, 240, 190};
inline constexpr Colour kIrCone{250, 210, 250};
inline constexpr Colour kTrail{120, 120, 0};
inline constexpr Colour kRobot{220, 30, 30};
inline constexpr Colour kTruth{0, 160, 0};
inline constexpr Colour kHypothesis{160, 0, 200};
inline constexpr Colour kFiducial{0, 130, 130};
inline constexpr Colour kText{0, 0, 0};
}  // namespace colours

}  // namespace playerkit::view
