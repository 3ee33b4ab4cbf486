#pragma once
// What the emulated CMUcam2 sees: colours by direction. The camera's frame is
// 88 x 143 pixels (the CMUcam2's low-resolution window), about 48 x 36
// degrees; the servos turn the frame over the scene. A scene is either an
// RGB image (one image pixel per frame pixel, its centre straight ahead at
// servo centre) or a synthetic one: coloured discs on a dark background.

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "families/cmucam2/protocol/cmucam_protocol.hpp"

namespace playerkit::emulators::cmucam2 {

inline constexpr int kFrameWidth = 88;
inline constexpr int kFrameHeight = 143;
inline constexpr double kDegreesPerColumn = 48.0 / kFrameWidth;
inline constexpr double kDegreesPerRow = 36.0 / kFrameHeight;

struct Rgb {
  std::uint8_t red = 0;
  std::uint8_t green = 0;
  std::uint8_t blue = 0;
};

struct RgbImage {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;  // row-major, row 0 at the top
};

// A binary (P6) or plain (P3) PPM, maxval up to 65535 scaled to 0..255. The
// project's readers (lib/image) give grey only, and colour is the point here.
// Throws std::invalid_argument naming the file and what is wrong.
[[nodiscard]] RgbImage read_ppm(const std::filesystem::path& file);

// A disc of one colour `radius` degrees across, centred at (pan, tilt) degrees.
struct Disc {
  double pan = 0;
  double tilt = 0;
  double radius = 1;
  Rgb color;
};

class Scene {
 public:
  Scene(std::vector<Disc> discs, Rgb background);
  explicit Scene(RgbImage image);

  // The colour seen in direction (pan, tilt), degrees; pan positive to the left, tilt up.
  [[nodiscard]] Rgb at(double pan, double tilt) const;
  [[nodiscard]] std::string describe() const;

 private:
  std::vector<Disc> discs_;
  Rgb background_;
  RgbImage image_;
};

// The middle-mass packet of the pixels within `bounds` in the frame seen
// with the camera turned to (pan, tilt) degrees: 1-based coordinates, the
// pixel count scaled (n + 4) / 8 and capped at 255, the confidence the
// share of the bounding box they fill, 0..255 (all zero when none match).
[[nodiscard]] hardware::cmucam2::TPacket track(const Scene& scene, const hardware::cmucam2::ColorBounds& bounds,
                                               double pan, double tilt);

}  // namespace playerkit::emulators::cmucam2
