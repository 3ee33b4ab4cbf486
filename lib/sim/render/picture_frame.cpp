#include "sim/render/picture_frame.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace playerkit::sim::render {
namespace {

int pixels_along(double metres, double pixels_per_metre, int max_side) {
  // The longer side is exactly max_side; rounding must not push the other past it.
  const double pixels = std::ceil(metres * pixels_per_metre - 1e-6);
  return std::clamp(static_cast<int>(pixels), 1, max_side);
}

}  // namespace

PictureFrame::PictureFrame(const Eigen::Vector2d& low, const Eigen::Vector2d& high, int max_side_pixels) {
  if (max_side_pixels < 1) throw std::invalid_argument("a picture needs at least one pixel a side");
  Eigen::Vector2d from = low.cwiseMin(high), to = low.cwiseMax(high);
  if (!from.allFinite() || !to.allFinite()) from = to = Eigen::Vector2d::Zero();
  if ((to - from).maxCoeff() <= 0.0) {
    const Eigen::Vector2d centre = 0.5 * (from + to);
    from = centre - Eigen::Vector2d::Constant(0.5);
    to = centre + Eigen::Vector2d::Constant(0.5);
  }
  const Eigen::Vector2d extent = (to - from).cwiseMax(0.0);
  pixels_per_metre_ = static_cast<double>(max_side_pixels) / extent.maxCoeff();
  width_ = pixels_along(extent.x(), pixels_per_metre_, max_side_pixels);
  height_ = pixels_along(extent.y(), pixels_per_metre_, max_side_pixels);
  low_ = from;
  high_ = from + Eigen::Vector2d(width_, height_) / pixels_per_metre_;
}

Eigen::Vector2d PictureFrame::to_pixel(const Eigen::Vector2d& world) const {
  return {(world.x() - low_.x()) * pixels_per_metre_, (high_.y() - world.y()) * pixels_per_metre_};
}

Eigen::Vector2d PictureFrame::to_world(const Eigen::Vector2d& pixel) const {
  return {low_.x() + pixel.x() / pixels_per_metre_, high_.y() - pixel.y() / pixels_per_metre_};
}

Eigen::Vector2i PictureFrame::pixel_of(const Eigen::Vector2d& world) const {
  const Eigen::Vector2d pixel = to_pixel(world);
  const auto index = [](double value) {
    constexpr double limit = 1.0e9;
    if (!(value > -limit)) return static_cast<int>(-limit);
    if (!(value < limit)) return static_cast<int>(limit);
    return static_cast<int>(std::floor(value));
  };
  return {index(pixel.x()), index(pixel.y())};
}

}  // namespace playerkit::sim::render
