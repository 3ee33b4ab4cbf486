#include "map/trajectory_plot.hpp"

#include "files/output_file.hpp"
#include "image/png.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>

namespace playerkit::map {
namespace {

constexpr std::uint8_t kFreeGrey = 255;
constexpr std::uint8_t kOccupiedGrey = 0;
constexpr std::uint8_t kUnknownGrey = 205;  // map_saver's unknown
const cv::Scalar kScanColour(0, 0, 255);    // BGR red
const cv::Scalar kPoseColour(0, 140, 255);  // BGR orange
// Drawing with fractional pixel positions: OpenCV's fixed-point `shift`.
constexpr int kShiftBits = 4;
constexpr double kShiftScale = 1 << kShiftBits;

// Half-open range of cells [col0, col1) x [row0, row1); may reach outside the grid.
struct CellBox {
  int col0 = 0, row0 = 0, col1 = 0, row1 = 0;
  int cols() const { return col1 - col0; }
  int rows() const { return row1 - row0; }
};

Eigen::Vector2d to_cells(const grid::OccupancyGrid& grid, const Eigen::Vector2d& world) {
  return (world - grid.origin()) / grid.resolution();
}

bool finite(const Eigen::Vector2d& point) { return point.allFinite(); }

// Known cells, every drawn point and a margin. A point absurdly far from the
// map would shrink the map to a dot, so the box reaches at most a few map
// sizes beyond the grid.
CellBox content_box(const grid::OccupancyGrid& grid, std::span<const PlotPath> paths,
                    std::span<const Eigen::Vector2d> scan_points,
                    const std::optional<geometry::Pose2>& final_pose) {
  const double reach = 4.0 * std::max(grid.width(), grid.height());
  Eigen::Vector2d low = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity());
  Eigen::Vector2d high = -low;
  const auto include = [&](const Eigen::Vector2d& cell) {
    const Eigen::Vector2d clamped(std::clamp(cell.x(), -reach, grid.width() + reach),
                                  std::clamp(cell.y(), -reach, grid.height() + reach));
    low = low.cwiseMin(clamped);
    high = high.cwiseMax(clamped);
  };
  for (int row = 0; row < grid.height(); ++row) {
    for (int col = 0; col < grid.width(); ++col) {
      if (grid.at(col, row) == grid::CellState::unknown) continue;
      include(Eigen::Vector2d(col, row));
      include(Eigen::Vector2d(col + 1, row + 1));
    }
  }
  for (const PlotPath& path : paths) {
    for (const Eigen::Vector2d& point : path.points) {
      if (finite(point)) include(to_cells(grid, point));
    }
  }
  for (const Eigen::Vector2d& point : scan_points) {
    if (finite(point)) include(to_cells(grid, point));
  }
  if (final_pose && finite(final_pose->translation())) {
    include(to_cells(grid, final_pose->translation()));
  }
  if (!(low.array() <= high.array()).all()) return {0, 0, grid.width(), grid.height()};

  const double longer = (high - low).maxCoeff();
  const int margin = std::max(2, static_cast<int>(std::ceil(0.03 * longer)));
  return {static_cast<int>(std::floor(low.x())) - margin,
          static_cast<int>(std::floor(low.y())) - margin,
          static_cast<int>(std::ceil(high.x())) + margin + (high.x() == low.x() ? 1 : 0),
          static_cast<int>(std::ceil(high.y())) + margin + (high.y() == low.y() ? 1 : 0)};
}

// Maps world metres to OpenCV drawing coordinates (pixel centres at integers).
class PixelMapping {
 public:
  PixelMapping(const grid::OccupancyGrid& grid, const CellBox& box, cv::Size size)
      : grid_(grid),
        box_(box),
        scale_x_(static_cast<double>(size.width) / box.cols()),
        scale_y_(static_cast<double>(size.height) / box.rows()) {}

  double column_pixel(double cell_x) const { return (cell_x - box_.col0) * scale_x_; }
  // Rows flip: the grid's lowest y is the image's bottom.
  double row_pixel(double cell_y) const { return (box_.row1 - cell_y) * scale_y_; }

  // Fixed-point, clamped so far-away points cannot overflow int.
  cv::Point point(const Eigen::Vector2d& world) const {
    const Eigen::Vector2d cell = to_cells(grid_, world);
    const auto fixed = [](double pixel) {
      return static_cast<int>(std::lround(std::clamp(pixel - 0.5, -1e7, 1e7) * kShiftScale));
    };
    return {fixed(column_pixel(cell.x())), fixed(row_pixel(cell.y()))};
  }

 private:
  const grid::OccupancyGrid& grid_;
  CellBox box_;
  double scale_x_, scale_y_;
};

cv::Size image_size(const CellBox& box, int max_side) {
  const int longer = std::max(box.cols(), box.rows());
  const double scale = longer <= max_side ? static_cast<double>(max_side / longer)
                                          : static_cast<double>(max_side) / longer;
  return {std::max(1, static_cast<int>(std::lround(box.cols() * scale))),
          std::max(1, static_cast<int>(std::lround(box.rows() * scale)))};
}

cv::Mat render_map(const grid::OccupancyGrid& grid, const CellBox& box, const PixelMapping& mapping,
                   cv::Size size) {
  cv::Mat canvas(size, CV_8UC1, cv::Scalar(kUnknownGrey));
  const CellBox inside{std::max(box.col0, 0), std::max(box.row0, 0),
                       std::min(box.col1, grid.width()), std::min(box.row1, grid.height())};
  if (inside.cols() <= 0 || inside.rows() <= 0) return canvas;

  cv::Mat cells(inside.rows(), inside.cols(), CV_8UC1);
  for (int row = inside.row0; row < inside.row1; ++row) {
    auto* pixels = cells.ptr<std::uint8_t>(inside.row1 - 1 - row);
    for (int col = inside.col0; col < inside.col1; ++col) {
      const grid::CellState state = grid.at(col, row);
      pixels[col - inside.col0] = state == grid::CellState::free       ? kFreeGrey
                                  : state == grid::CellState::occupied ? kOccupiedGrey
                                                                       : kUnknownGrey;
    }
  }
  const int left = static_cast<int>(std::lround(mapping.column_pixel(inside.col0)));
  const int right = static_cast<int>(std::lround(mapping.column_pixel(inside.col1)));
  const int top = static_cast<int>(std::lround(mapping.row_pixel(inside.row1)));
  const int bottom = static_cast<int>(std::lround(mapping.row_pixel(inside.row0)));
  if (right <= left || bottom <= top) return canvas;
  // Nearest keeps enlarged cells crisp; area averaging keeps thin walls visible when shrinking.
  const bool enlarging = right - left >= inside.cols();
  cv::resize(cells, canvas(cv::Rect(left, top, right - left, bottom - top)),
             cv::Size(right - left, bottom - top), 0, 0,
             enlarging ? cv::INTER_NEAREST : cv::INTER_AREA);
  return canvas;
}

cv::Scalar bgr(const std::array<std::uint8_t, 3>& rgb) {
  return cv::Scalar(rgb[2], rgb[1], rgb[0]);
}

void draw_legend(cv::Mat& image, std::span<const PlotPath> paths, bool has_scan, bool has_pose,
                 int line_thickness) {
  struct Entry {
    std::string text;
    cv::Scalar colour;
    bool dot;
  };
  std::vector<Entry> entries;
  for (const PlotPath& path : paths) {
    if (!path.label.empty()) entries.push_back({path.label, bgr(path.rgb), false});
  }
  if (has_scan) entries.push_back({"last scan", kScanColour, true});
  if (has_pose) entries.push_back({"final pose", kPoseColour, false});
  if (entries.empty()) return;

  const int longer = std::max(image.cols, image.rows);
  const double font_scale = std::clamp(longer / 1500.0, 0.35, 1.2);
  const int font = cv::FONT_HERSHEY_SIMPLEX;
  int baseline = 0;
  const int text_height = cv::getTextSize("Ag", font, font_scale, 1, &baseline).height;
  const int line_height = text_height + baseline + 4;
  const int swatch = 2 * text_height;
  int text_width = 0;
  for (const Entry& entry : entries) {
    text_width =
        std::max(text_width, cv::getTextSize(entry.text, font, font_scale, 1, &baseline).width);
  }
  const int pad = 4;
  const cv::Rect frame(pad, pad, 3 * pad + swatch + text_width,
                       2 * pad + line_height * static_cast<int>(entries.size()));
  // A thumbnail is better without a legend than hidden behind one.
  if (2 * frame.br().x > image.cols || 2 * frame.br().y > image.rows) return;
  cv::rectangle(image, frame, cv::Scalar(255, 255, 255), cv::FILLED);
  cv::rectangle(image, frame, cv::Scalar(0, 0, 0), 1);
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const int centre_y = frame.y + pad + line_height * static_cast<int>(i) + line_height / 2;
    const int swatch_x = frame.x + pad;
    if (entries[i].dot) {
      cv::circle(image, {swatch_x + swatch / 2, centre_y}, std::max(2, line_thickness),
                 entries[i].colour, cv::FILLED, cv::LINE_AA);
    } else {
      cv::line(image, {swatch_x, centre_y}, {swatch_x + swatch, centre_y}, entries[i].colour,
               line_thickness, cv::LINE_AA);
    }
    cv::putText(image, entries[i].text, {swatch_x + swatch + pad, centre_y + text_height / 2}, font,
                font_scale, cv::Scalar(0, 0, 0), 1, cv::LINE_AA);
  }
}

}  // namespace

void write_trajectory_plot(const std::filesystem::path& png, const grid::OccupancyGrid& grid,
                           std::span<const PlotPath> paths,
                           std::span<const Eigen::Vector2d> scan_points,
                           const std::optional<geometry::Pose2>& final_pose,
                           const PlotOptions& options) {
  if (grid.empty()) throw std::invalid_argument("write_trajectory_plot: empty grid");
  if (options.max_side_pixels <= 0) {
    throw std::invalid_argument("write_trajectory_plot: max_side_pixels must be positive");
  }
  const CellBox box = options.crop_to_content ? content_box(grid, paths, scan_points, final_pose)
                                              : CellBox{0, 0, grid.width(), grid.height()};
  const cv::Size size = image_size(box, options.max_side_pixels);
  const PixelMapping mapping(grid, box, size);
  cv::Mat image;
  cv::cvtColor(render_map(grid, box, mapping, size), image, cv::COLOR_GRAY2BGR);

  const int longer = std::max(size.width, size.height);
  const int thickness = std::max(1, longer / 500);
  for (const PlotPath& path : paths) {
    std::vector<cv::Point> polyline;
    for (const Eigen::Vector2d& point : path.points) {
      if (finite(point)) polyline.push_back(mapping.point(point));
    }
    if (polyline.size() == 1) polyline.push_back(polyline.front());  // a lone pose is still seen
    if (!polyline.empty()) {
      cv::polylines(image, polyline, false, bgr(path.rgb), thickness, cv::LINE_AA, kShiftBits);
    }
  }
  const int dot_radius = std::max(1, thickness);
  for (const Eigen::Vector2d& point : scan_points) {
    if (!finite(point)) continue;
    cv::circle(image, mapping.point(point), dot_radius * static_cast<int>(kShiftScale), kScanColour,
               cv::FILLED, cv::LINE_AA, kShiftBits);
  }
  const bool pose_drawn =
      final_pose && finite(final_pose->translation()) && std::isfinite(final_pose->yaw);
  if (pose_drawn) {
    // Long enough to read the heading at any zoom, independent of the map's resolution.
    const double length_pixels = std::max(15.0, 0.04 * longer);
    const cv::Point base = mapping.point(final_pose->translation());
    const double shaft = length_pixels * kShiftScale, yaw = final_pose->yaw;
    const cv::Point tip = base + cv::Point(static_cast<int>(std::lround(std::cos(yaw) * shaft)),
                                           static_cast<int>(std::lround(-std::sin(yaw) * shaft)));
    cv::arrowedLine(image, base, tip, kPoseColour, thickness + 1, cv::LINE_AA, kShiftBits, 0.3);
  }
  draw_legend(image, paths, !scan_points.empty(), pose_drawn, thickness);

  cv::Mat rgb;
  cv::cvtColor(image, rgb, cv::COLOR_BGR2RGB);
  const std::vector<std::uint8_t> encoded =
      playerkit::image::encode_png({rgb.data, rgb.total() * 3}, rgb.cols, rgb.rows, 3);
  try {
    files::OutputFile out(png, {.compression = files::Compression::kNone});
    out.stream().write(reinterpret_cast<const char*>(encoded.data()),
                       static_cast<std::streamsize>(encoded.size()));
    out.commit();
  } catch (const files::OutputError&) {
    throw MapFileError(png, "cannot write the plot");
  }
}

}  // namespace playerkit::map
