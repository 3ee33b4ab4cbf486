#pragma once
// Where the world lies in a picture: a box of world metres scaled to
// pixels, square pixels, x to the right and y up. Pixel (col, row) covers
// [col, col + 1) x [row, row + 1) in continuous pixel coordinates, row 0 at
// the top.

#include <Eigen/Core>

namespace playerkit::sim::render {

class PictureFrame {
 public:
  // The box [low, high] (metres) at the scale that makes its longer side
  // `max_side_pixels`. A box of zero or non-finite size becomes one metre
  // around its centre (the origin when nothing is finite). Throws
  // std::invalid_argument for a max_side_pixels below 1.
  PictureFrame(const Eigen::Vector2d& low, const Eigen::Vector2d& high, int max_side_pixels);

  [[nodiscard]] int width() const { return width_; }
  [[nodiscard]] int height() const { return height_; }
  [[nodiscard]] double pixels_per_metre() const { return pixels_per_metre_; }
  [[nodiscard]] const Eigen::Vector2d& low() const { return low_; }    // world corner at the bottom left
  [[nodiscard]] const Eigen::Vector2d& high() const { return high_; }  // and at the top right

  // Continuous pixel coordinates of a world point (may lie outside).
  [[nodiscard]] Eigen::Vector2d to_pixel(const Eigen::Vector2d& world) const;
  // The world point at continuous pixel coordinates.
  [[nodiscard]] Eigen::Vector2d to_world(const Eigen::Vector2d& pixel) const;
  // The pixel holding a world point (may lie outside the picture).
  [[nodiscard]] Eigen::Vector2i pixel_of(const Eigen::Vector2d& world) const;
  [[nodiscard]] bool contains(const Eigen::Vector2i& pixel) const {
    return pixel.x() >= 0 && pixel.y() >= 0 && pixel.x() < width_ && pixel.y() < height_;
  }

 private:
  Eigen::Vector2d low_;
  Eigen::Vector2d high_;
  double pixels_per_metre_ = 1.0;
  int width_ = 1;
  int height_ = 1;
};

}  // namespace playerkit::sim::render
