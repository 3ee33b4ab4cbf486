#include "view/renderer.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string>

#include "files/output_file.hpp"
#include "image/png.hpp"

namespace playerkit::view {
namespace {

// Sub-pixel positions for OpenCV's drawing: 4 fractional bits.
constexpr int kShiftBits = 4;
constexpr double kShiftScale = 1 << kShiftBits;

constexpr std::uint8_t kFree = 255, kOccupied = 0, kUnknown = 205;
constexpr std::uint8_t kGridLine = 232;

// The image holds R, G, B in that order: the bytes go to the PNG encoder as
// they are, so a Scalar is written (r, g, b).
cv::Scalar scalar(Colour colour) { return {double(colour.r), double(colour.g), double(colour.b)}; }

class Painter {
 public:
  Painter(cv::Mat& image, const ViewTransform& transform) : image_(image), transform_(transform) {}

  // A far-away point must not overflow OpenCV's int coordinates.
  [[nodiscard]] cv::Point shifted(const Point& world) const {
    const Point pixel = transform_.to_pixel(world);
    static constexpr double kLimit = 1.0e6;
    const auto fixed = [](double v) {
      return static_cast<int>(std::lround(std::clamp(v, -kLimit, kLimit) * kShiftScale));
    };
    return {fixed(pixel.x), fixed(pixel.y)};
  }

  [[nodiscard]] std::vector<cv::Point> shifted(const std::vector<Point>& points) const {
    std::vector<cv::Point> out;
    out.reserve(points.size());
    for (const auto& point : points) out.push_back(shifted(point));
    return out;
  }

  void area(const Area& area) {
    if (area.points.size() < 3) return;
    const std::vector<std::vector<cv::Point>> polygons{shifted(area.points)};
    cv::fillPoly(image_, polygons, scalar(area.fill), cv::LINE_AA, kShiftBits);
  }

  void line(const Line& line) {
    if (line.points.size() < 2) return;
    const std::vector<std::vector<cv::Point>> lines{shifted(line.points)};
    cv::polylines(image_, lines, false, scalar(line.colour), 2, cv::LINE_AA, kShiftBits);
  }

  void dots(const Dots& dots) {
    for (const auto& point : dots.points) {
      cv::circle(image_, shifted(point), dots.radius_pixels << kShiftBits, scalar(dots.colour), cv::FILLED,
                 cv::LINE_8, kShiftBits);
    }
  }

  void ellipse(const Ellipse& ellipse) {
    const double scale = transform_.pixels_per_metre * kShiftScale;
    const cv::Size axes(std::max(1, static_cast<int>(std::lround(std::min(ellipse.semi_major * scale, 1.0e6)))),
                        std::max(1, static_cast<int>(std::lround(std::min(ellipse.semi_minor * scale, 1.0e6)))));
    // Image rows grow downwards, so angles turn the other way.
    const double degrees = -ellipse.angle * 180.0 / CV_PI;
    cv::ellipse(image_, shifted(ellipse.centre), axes, degrees, 0, 360, scalar(ellipse.colour), 2, cv::LINE_AA,
                kShiftBits);
  }

  void body(const Body& body) {
    const double c = std::cos(body.pose.yaw), s = std::sin(body.pose.yaw);
    const auto corner = [&](double along, double across) {
      return Point{body.pose.x + c * along - s * across, body.pose.y + s * along + c * across};
    };
    const double l = 0.5 * body.length, w = 0.5 * body.width;
    const std::vector<cv::Point> box =
        shifted(std::vector<Point>{corner(l, w), corner(-l, w), corner(-l, -w), corner(l, -w)});
    if (body.filled) {
      cv::fillConvexPoly(image_, box, scalar(body.colour), cv::LINE_AA, kShiftBits);
    } else {
      cv::polylines(image_, std::vector<std::vector<cv::Point>>{box}, true, scalar(body.colour), 2, cv::LINE_AA,
                    kShiftBits);
    }
    // The heading, in a colour that shows on the filled box and off it.
    const Colour heading = body.filled ? Colour{255, 255, 255} : body.colour;
    cv::line(image_, shifted(corner(0, 0)), shifted(corner(l * 1.4, 0)), scalar(heading), 2, cv::LINE_AA, kShiftBits);
  }

 private:
  cv::Mat& image_;
  const ViewTransform& transform_;
};

// Returns the pixels that show a wall, to paint again over the sensors' areas.
std::vector<cv::Point> draw_map(cv::Mat& image, const ViewTransform& view, const grid::OccupancyGrid& map) {
  std::vector<cv::Point> walls;
  // The cell of each column and each row once; a pixel is their pair.
  const auto world_x = [&](int col) { return view.centre.x + (col + 0.5 - 0.5 * view.width) / view.pixels_per_metre; };
  const auto world_y = [&](int row) {
    return view.centre.y - (row + 0.5 - 0.5 * view.height) / view.pixels_per_metre;
  };
  std::vector<int> cols(static_cast<std::size_t>(view.width)), rows(static_cast<std::size_t>(view.height));
  for (int col = 0; col < view.width; ++col) {
    cols[static_cast<std::size_t>(col)] = map.world_to_cell({world_x(col), 0.0}).x();
  }
  for (int row = 0; row < view.height; ++row) {
    rows[static_cast<std::size_t>(row)] = map.world_to_cell({0.0, world_y(row)}).y();
  }
  for (int row = 0; row < view.height; ++row) {
    auto* out = image.ptr<std::uint8_t>(row);
    for (int col = 0; col < view.width; ++col) {
      const int cx = cols[static_cast<std::size_t>(col)], cy = rows[static_cast<std::size_t>(row)];
      std::uint8_t grey = kUnknown;
      if (map.contains(cx, cy)) {
        const auto state = map.at(cx, cy);
        grey = state == grid::CellState::free ? kFree : state == grid::CellState::occupied ? kOccupied : kUnknown;
        if (grey == kOccupied) walls.emplace_back(col, row);
      }
      out[3 * col] = out[3 * col + 1] = out[3 * col + 2] = grey;
    }
  }
  return walls;
}

void draw_metre_grid(cv::Mat& image, const ViewTransform& view) {
  // Too dense to help below 8 pixels a metre.
  if (view.pixels_per_metre < 8.0) return;
  const double left = view.centre.x - 0.5 * view.width / view.pixels_per_metre;
  const double bottom = view.centre.y - 0.5 * view.height / view.pixels_per_metre;
  const cv::Scalar colour(kGridLine, kGridLine, kGridLine);
  for (double x = std::ceil(left); x < left + view.width / view.pixels_per_metre; x += 1.0) {
    const int col = static_cast<int>(std::floor(view.to_pixel({x, 0}).x));
    cv::line(image, {col, 0}, {col, view.height - 1}, colour, 1);
  }
  for (double y = std::ceil(bottom); y < bottom + view.height / view.pixels_per_metre; y += 1.0) {
    const int row = static_cast<int>(std::floor(view.to_pixel({0, y}).y));
    cv::line(image, {0, row}, {view.width - 1, row}, colour, 1);
  }
}

// 1, 2 or 5 times a power of ten, about a fifth of the picture's width.
double scale_bar_metres(double picture_metres) {
  const double wanted = picture_metres / 5.0;
  const double power = std::pow(10.0, std::floor(std::log10(wanted)));
  for (const double step : {5.0, 2.0, 1.0}) {
    if (step * power <= wanted) return step * power;
  }
  return power;
}

std::string metres_text(double metres) {
  if (metres >= 1.0) return std::to_string(static_cast<long>(std::lround(metres))) + " m";
  return std::to_string(static_cast<long>(std::lround(metres * 100.0))) + " cm";
}

void draw_text_box(cv::Mat& image, const std::string& text, cv::Point origin, Colour colour) {
  constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
  constexpr double kFontScale = 0.45;
  int baseline = 0;
  const cv::Size size = cv::getTextSize(text, kFont, kFontScale, 1, &baseline);
  cv::rectangle(image, origin + cv::Point(-2, baseline + 1), origin + cv::Point(size.width + 2, -size.height - 2),
                cv::Scalar(255, 255, 255), cv::FILLED);
  cv::putText(image, text, origin, kFont, kFontScale, scalar(colour), 1, cv::LINE_AA);
}

void draw_scale_bar(cv::Mat& image, const ViewTransform& view) {
  const double metres = scale_bar_metres(view.width / view.pixels_per_metre);
  const int length = static_cast<int>(std::lround(metres * view.pixels_per_metre));
  const cv::Point left(10, view.height - 12);
  draw_text_box(image, metres_text(metres), left + cv::Point(length + 6, 4), colours::kText);
  cv::line(image, left, left + cv::Point(length, 0), scalar(colours::kText), 3);
}

}  // namespace

ViewTransform view_transform(const Frame& frame, const RenderOptions& options) {
  return {frame.centre, options.width / options.span, options.width, options.height};
}

RgbImage render(const Frame& frame, const grid::OccupancyGrid* map, const RenderOptions& options) {
  constexpr int kMinSide = 16, kMaxSide = 8192;
  if (options.width < kMinSide || options.height < kMinSide || options.width > kMaxSide ||
      options.height > kMaxSide) {
    throw std::invalid_argument("a picture is 16 to 8192 pixels on each side");
  }
  if (!std::isfinite(options.span) || options.span <= 0.0) {
    throw std::invalid_argument("the picture's span must be a positive number of metres");
  }
  const ViewTransform view = view_transform(frame, options);
  cv::Mat image(options.height, options.width, CV_8UC3, cv::Scalar(kFree, kFree, kFree));
  std::vector<cv::Point> walls;
  if (map && !map->empty()) {
    walls = draw_map(image, view, *map);
  } else {
    draw_metre_grid(image, view);
  }
  Painter painter(image, view);
  for (const auto& area : frame.areas) painter.area(area);
  // Walls stay visible through the cones and fans (a sonar cone is wider
  // than the wall it hit); what was measured on them is drawn next.
  for (const auto& wall : walls) image.at<cv::Vec3b>(wall) = cv::Vec3b(kOccupied, kOccupied, kOccupied);
  for (const auto& line : frame.lines) painter.line(line);
  for (const auto& dots : frame.dots) painter.dots(dots);
  for (const auto& ellipse : frame.ellipses) painter.ellipse(ellipse);
  for (const auto& body : frame.bodies) painter.body(body);
  for (const auto& label : frame.labels) {
    const Point pixel = view.to_pixel(label.at);
    // Beside the point, not on it: the marker stays visible.
    if (std::abs(pixel.x) < 1.0e6 && std::abs(pixel.y) < 1.0e6) {
      cv::putText(image, label.text, {static_cast<int>(pixel.x) + 6, static_cast<int>(pixel.y) - 6},
                  cv::FONT_HERSHEY_SIMPLEX, 0.45, scalar(label.colour), 1, cv::LINE_AA);
    }
  }
  int row = 18;
  for (const auto& entry : frame.legend) {
    draw_text_box(image, entry.text, {8, row}, entry.colour);
    row += 18;
  }
  draw_scale_bar(image, view);

  RgbImage out{options.width, options.height, {}};
  out.pixels.assign(image.datastart, image.dataend);
  return out;
}

void write_png(const std::filesystem::path& path, const RgbImage& image) {
  const auto encoded = image::encode_png(image.pixels, image.width, image.height, 3);
  files::OutputFile out(path, {.compression = files::Compression::kNone});
  out.stream().write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
  out.commit();
}

}  // namespace playerkit::view
