#include "sim/render/world_picture.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <string>

namespace playerkit::sim::render {
namespace {

// OpenCV draws at fractional pixel positions through a fixed-point `shift`;
// its integer coordinates are pixel centres.
constexpr int kPictureShiftBits = 4;
constexpr double kPictureShiftScale = 1 << kPictureShiftBits;

cv::Scalar bgr_of(const Rgb& color) { return {double(color.b), double(color.g), double(color.r)}; }

Rgb darker(const Rgb& color) {
  const auto scale = [](std::uint8_t channel) { return static_cast<std::uint8_t>(channel * 3 / 5); };
  return {scale(color.r), scale(color.g), scale(color.b)};
}

class PictureCanvas {
 public:
  PictureCanvas(const PictureFrame& frame, cv::Mat& image) : frame_(frame), image_(image) {}

  [[nodiscard]] cv::Point point(const Eigen::Vector2d& world) const {
    const Eigen::Vector2d pixel = frame_.to_pixel(world);
    const auto fixed = [](double value) {
      return static_cast<int>(std::lround(std::clamp(value - 0.5, -1e6, 1e6) * kPictureShiftScale));
    };
    return {fixed(pixel.x()), fixed(pixel.y())};
  }
  // A length in metres as pixels, at least `least`.
  [[nodiscard]] int pixels(double metres, int least) const {
    return std::max(least, static_cast<int>(std::lround(metres * frame_.pixels_per_metre())));
  }
  [[nodiscard]] int fixed_pixels(double metres) const {
    return std::max(1, static_cast<int>(std::lround(metres * frame_.pixels_per_metre() * kPictureShiftScale)));
  }
  [[nodiscard]] const PictureFrame& frame() const { return frame_; }
  [[nodiscard]] cv::Mat& image() const { return image_; }

 private:
  const PictureFrame& frame_;
  cv::Mat& image_;
};

void set_pixel(cv::Mat& image, int col, int row, const Rgb& color) {
  image.at<cv::Vec3b>(row, col) = cv::Vec3b(color.b, color.g, color.r);
}

// Each pixel shows the cell under its centre; a wall cell smaller than a
// pixel still darkens the pixel holding its centre, so thin walls survive
// a shrunk map.
void draw_map(const PictureCanvas& canvas, const grid::OccupancyGrid& map) {
  const PictureFrame& frame = canvas.frame();
  cv::Mat& image = canvas.image();
  // The cell column of every pixel column and the cell row of every pixel row, once.
  std::vector<int> cell_cols(static_cast<std::size_t>(frame.width()));
  std::vector<int> cell_rows(static_cast<std::size_t>(frame.height()));
  for (int col = 0; col < frame.width(); ++col) {
    cell_cols[static_cast<std::size_t>(col)] = map.world_to_cell(frame.to_world({col + 0.5, 0.5})).x();
  }
  for (int row = 0; row < frame.height(); ++row) {
    cell_rows[static_cast<std::size_t>(row)] = map.world_to_cell(frame.to_world({0.5, row + 0.5})).y();
  }
  for (int row = 0; row < frame.height(); ++row) {
    const int cell_row = cell_rows[static_cast<std::size_t>(row)];
    for (int col = 0; col < frame.width(); ++col) {
      const int cell_col = cell_cols[static_cast<std::size_t>(col)];
      const grid::CellState state =
          map.contains(cell_col, cell_row) ? map.at(cell_col, cell_row) : grid::CellState::unknown;
      set_pixel(image, col, row,
                state == grid::CellState::free       ? colors::kFloor
                : state == grid::CellState::occupied ? colors::kWall
                                                     : colors::kUnknown);
    }
  }
  for (int row = 0; row < map.height(); ++row) {
    for (int col = 0; col < map.width(); ++col) {
      if (map.at(col, row) != grid::CellState::occupied) continue;
      const Eigen::Vector2i pixel = frame.pixel_of(map.cell_centre({col, row}));
      if (frame.contains(pixel)) set_pixel(image, pixel.x(), pixel.y(), colors::kWall);
    }
  }
}

// Faint: every ray of a kind marks a mask, and the marked pixels are
// blended once, so crossing rays do not darken each other.
void draw_rays(const PictureCanvas& canvas, const std::vector<SnapshotRay>& rays, RayKind kind) {
  cv::Mat& image = canvas.image();
  cv::Mat mask = cv::Mat::zeros(image.size(), CV_8UC1);
  bool any = false;
  for (const SnapshotRay& ray : rays) {
    if (ray.kind != kind) continue;
    cv::line(mask, canvas.point(ray.from), canvas.point(ray.to), cv::Scalar(255), 1, cv::LINE_8, kPictureShiftBits);
    any = true;
  }
  if (!any) return;
  const Rgb tint = kind == RayKind::laser ? colors::kLaserRay : colors::kSonarRay;
  const double opacity = colors::kRayOpacity;
  const auto blend = [opacity](std::uint8_t below, std::uint8_t over) {
    return cv::saturate_cast<std::uint8_t>(std::lround(below * (1.0 - opacity) + over * opacity));
  };
  for (int row = 0; row < image.rows; ++row) {
    const auto* marks = mask.ptr<std::uint8_t>(row);
    auto* pixels = image.ptr<cv::Vec3b>(row);
    for (int col = 0; col < image.cols; ++col) {
      if (marks[col] == 0) continue;
      cv::Vec3b& pixel = pixels[col];
      pixel = cv::Vec3b(blend(pixel[0], tint.b), blend(pixel[1], tint.g), blend(pixel[2], tint.r));
    }
  }
  const Rgb hit_color = kind == RayKind::laser ? colors::kLaserHit : colors::kSonarHit;
  const int radius = canvas.pixels(0.015, 1) * static_cast<int>(kPictureShiftScale);
  for (const SnapshotRay& ray : rays) {
    if (ray.kind != kind || !ray.hit) continue;
    cv::circle(image, canvas.point(ray.to), radius, bgr_of(hit_color), cv::FILLED, cv::LINE_AA, kPictureShiftBits);
  }
}

void draw_trails(const PictureCanvas& canvas, const std::vector<SnapshotTrail>& trails) {
  const int thickness = canvas.pixels(0.02, 1);
  for (const SnapshotTrail& trail : trails) {
    std::vector<cv::Point> polyline;
    polyline.reserve(trail.points.size());
    for (const Eigen::Vector2d& point : trail.points) polyline.push_back(canvas.point(point));
    if (polyline.size() < 2) continue;
    cv::polylines(canvas.image(), polyline, false, bgr_of(darker(trail.color)), thickness, cv::LINE_AA,
                  kPictureShiftBits);
  }
}

void draw_sightings(const PictureCanvas& canvas, const std::vector<SnapshotSighting>& sightings) {
  const cv::Scalar color = bgr_of(colors::kSighting);
  const int ring = canvas.pixels(0.12, 3) * static_cast<int>(kPictureShiftScale);
  const double font_scale = std::clamp(canvas.frame().pixels_per_metre() / 200.0, 0.35, 0.8);
  for (const SnapshotSighting& sighting : sightings) {
    const cv::Point to = canvas.point(sighting.to);
    cv::line(canvas.image(), canvas.point(sighting.from), to, color, 1, cv::LINE_AA, kPictureShiftBits);
    cv::circle(canvas.image(), to, ring, color, 1, cv::LINE_AA, kPictureShiftBits);
    const cv::Point label(to.x / static_cast<int>(kPictureShiftScale) + ring / static_cast<int>(kPictureShiftScale) + 2,
                          to.y / static_cast<int>(kPictureShiftScale));
    cv::putText(canvas.image(), std::to_string(sighting.id), label, cv::FONT_HERSHEY_SIMPLEX, font_scale, color, 1,
                cv::LINE_AA);
  }
}

void draw_body(const PictureCanvas& canvas, const SnapshotBody& body) {
  cv::Mat& image = canvas.image();
  const cv::Scalar fill = bgr_of(body.color);
  const cv::Scalar outline = bgr_of(darker(body.color));
  if (body.shape == Shape::circle) {
    const cv::Point centre = canvas.point(body.pose.translation());
    const int radius = canvas.fixed_pixels(body.size.x() / 2.0);
    cv::circle(image, centre, radius, fill, cv::FILLED, cv::LINE_AA, kPictureShiftBits);
    cv::circle(image, centre, radius, outline, 1, cv::LINE_AA, kPictureShiftBits);
  } else {
    const double half_x = body.size.x() / 2.0, half_y = body.size.y() / 2.0;
    std::vector<cv::Point> corners;
    for (const auto& [x, y] : {std::pair{half_x, half_y}, {-half_x, half_y}, {-half_x, -half_y}, {half_x, -half_y}}) {
      corners.push_back(canvas.point(body.pose.compose({x, y, 0.0}).translation()));
    }
    cv::fillConvexPoly(image, corners, fill, cv::LINE_AA, kPictureShiftBits);
    cv::polylines(image, corners, true, outline, 1, cv::LINE_AA, kPictureShiftBits);
  }
}

// After every body, so the sensors riding on a robot do not hide it.
void draw_heading(const PictureCanvas& canvas, const SnapshotBody& body) {
  // From the body's centre to the middle of its front edge.
  const Eigen::Vector2d front = body.pose.compose({body.size.x() / 2.0, 0.0, 0.0}).translation();
  cv::line(canvas.image(), canvas.point(body.pose.translation()), canvas.point(front), bgr_of(colors::kHeading),
           canvas.pixels(0.015, 1), cv::LINE_AA, kPictureShiftBits);
}

void draw_caption(cv::Mat& image, double time) {
  char text[64];
  std::snprintf(text, sizeof text, "t = %.1f s", time);
  const double font_scale = std::clamp(std::max(image.cols, image.rows) / 1600.0, 0.35, 0.8);
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, font_scale, 1, &baseline);
  const int pad = 3;
  // A thumbnail is better without a caption than hidden behind one.
  if (2 * (size.width + 2 * pad) > image.cols || 2 * (size.height + baseline + 2 * pad) > image.rows) return;
  cv::rectangle(image, cv::Rect(0, 0, size.width + 2 * pad, size.height + baseline + 2 * pad),
                cv::Scalar(255, 255, 255), cv::FILLED);
  cv::putText(image, text, {pad, pad + size.height}, cv::FONT_HERSHEY_SIMPLEX, font_scale, cv::Scalar(0, 0, 0), 1,
              cv::LINE_AA);
}

}  // namespace

Rgb Picture::at(int col, int row) const {
  const std::size_t offset =
      (static_cast<std::size_t>(row) * static_cast<std::size_t>(width()) + static_cast<std::size_t>(col)) * 3;
  return {rgb[offset], rgb[offset + 1], rgb[offset + 2]};
}

PictureFrame frame_for(const WorldSnapshot& snapshot, int max_side_pixels) {
  constexpr double inf = std::numeric_limits<double>::infinity();
  Eigen::Vector2d low = Eigen::Vector2d::Constant(inf), high = Eigen::Vector2d::Constant(-inf);
  Eigen::Vector2d reach_low = Eigen::Vector2d::Constant(-inf), reach_high = Eigen::Vector2d::Constant(inf);
  if (snapshot.map != nullptr && !snapshot.map->empty()) {
    const grid::OccupancyGrid& map = *snapshot.map;
    low = map.origin();
    high = map.origin() + map.resolution() * Eigen::Vector2d(map.width(), map.height());
    reach_low = low - 2.0 * (high - low);
    reach_high = high + 2.0 * (high - low);
  }
  const auto include = [&](const Eigen::Vector2d& point, double radius) {
    if (!point.allFinite() || !std::isfinite(radius)) return;
    const Eigen::Vector2d clamped = point.cwiseMax(reach_low).cwiseMin(reach_high);
    low = low.cwiseMin(clamped - Eigen::Vector2d::Constant(radius));
    high = high.cwiseMax(clamped + Eigen::Vector2d::Constant(radius));
  };
  for (const SnapshotBody& body : snapshot.bodies) {
    const double radius = body.shape == Shape::circle ? body.size.x() / 2.0 : body.size.norm() / 2.0;
    include(body.pose.translation(), radius);
  }
  for (const SnapshotTrail& trail : snapshot.trails) {
    for (const Eigen::Vector2d& point : trail.points) include(point, 0.0);
  }
  return PictureFrame(low, high, max_side_pixels);
}

Picture draw_world(const WorldSnapshot& snapshot, const PictureOptions& options) {
  Picture picture{.frame = frame_for(snapshot, options.max_side_pixels), .rgb = {}};
  cv::Mat image(picture.height(), picture.width(), CV_8UC3, bgr_of(colors::kUnknown));
  const PictureCanvas canvas(picture.frame, image);
  if (snapshot.map != nullptr && !snapshot.map->empty()) draw_map(canvas, *snapshot.map);
  draw_rays(canvas, snapshot.rays, RayKind::sonar);
  draw_rays(canvas, snapshot.rays, RayKind::laser);
  draw_trails(canvas, snapshot.trails);
  draw_sightings(canvas, snapshot.sightings);
  for (const SnapshotBody& body : snapshot.bodies) draw_body(canvas, body);
  for (const SnapshotBody& body : snapshot.bodies) {
    if (body.robot) draw_heading(canvas, body);
  }
  if (options.caption) draw_caption(image, snapshot.time);

  cv::Mat rgb;
  cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
  picture.rgb.assign(rgb.datastart, rgb.dataend);
  return picture;
}

}  // namespace playerkit::sim::render
