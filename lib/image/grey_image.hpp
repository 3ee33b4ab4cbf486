#pragma once
// An 8-bit grey image and what decoding one can answer.

#include <cstdint>
#include <string>
#include <vector>

namespace playerkit::image {

struct GreyImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // row-major, row 0 at the top, as in the file
};

struct Decoded {
  GreyImage image;
  std::string error;  // empty when the image was decoded
  bool ok() const { return error.empty(); }
};

// The width and height a file's header declares, read before decoding so
// that a caller can refuse an absurd size without taking the memory.
struct DeclaredSize {
  std::int64_t width = 0;
  std::int64_t height = 0;
};

// Colour to grey as OpenCV's and libpng's grey conversions weigh it
// (0.299 R + 0.587 G + 0.114 B), in 15-bit fixed point.
inline std::uint8_t grey_of(unsigned red, unsigned green, unsigned blue) {
  return static_cast<std::uint8_t>((9798u * red + 19235u * green + 3735u * blue + 16384u) >> 15);
}

// The most pixels a decoder accepts (a header may claim anything).
inline constexpr std::int64_t kMaxPixels = std::int64_t{1} << 28;

}  // namespace playerkit::image
