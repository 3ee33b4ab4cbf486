#include "families/cmucam2/emulator/cmucam_scene.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <stdexcept>

namespace playerkit::emulators::cmucam2 {

namespace {

// PPM header fields: whitespace and # comments between them.
class PpmReader {
 public:
  PpmReader(std::string bytes, std::string name) : bytes_(std::move(bytes)), name_(std::move(name)) {}

  int number() {
    skip_space();
    if (at_ >= bytes_.size() || !std::isdigit(static_cast<unsigned char>(bytes_[at_]))) fail("a number expected");
    long value = 0;
    while (at_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[at_]))) {
      value = value * 10 + (bytes_[at_++] - '0');
      if (value > 1'000'000) fail("a number too large");
    }
    return static_cast<int>(value);
  }
  std::uint8_t raw() {
    if (at_ >= bytes_.size()) fail("the pixels end early");
    return static_cast<std::uint8_t>(bytes_[at_++]);
  }
  void one_space() { ++at_; }
  [[noreturn]] void fail(const std::string& why) const {
    throw std::invalid_argument("cmucam2: image " + name_ + ": not a PPM the emulator reads: " + why);
  }
  [[nodiscard]] std::string_view magic() const { return std::string_view(bytes_).substr(0, 2); }
  void skip_magic() { at_ = 2; }

 private:
  void skip_space() {
    while (at_ < bytes_.size()) {
      if (bytes_[at_] == '#') {
        while (at_ < bytes_.size() && bytes_[at_] != '\n') ++at_;
      } else if (std::isspace(static_cast<unsigned char>(bytes_[at_]))) {
        ++at_;
      } else {
        return;
      }
    }
  }
  std::string bytes_;
  std::string name_;
  std::size_t at_ = 0;
};

}  // namespace

RgbImage read_ppm(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::invalid_argument("cmucam2: image " + file.string() + ": cannot be read");
  PpmReader reader(std::string(std::istreambuf_iterator<char>(in), {}), file.string());
  const bool binary = reader.magic() == "P6";
  if (!binary && reader.magic() != "P3") reader.fail("P6 or P3 expected (convert with `pnmtoppm` or `convert x.png x.ppm`)");
  reader.skip_magic();
  RgbImage image;
  image.width = reader.number();
  image.height = reader.number();
  const int maxval = reader.number();
  if (image.width <= 0 || image.height <= 0 || maxval <= 0 || maxval > 65535) reader.fail("a bad size or maxval");
  if (static_cast<long>(image.width) * image.height > 16'000'000) reader.fail("more than 16 million pixels");
  if (binary) reader.one_space();
  const auto sample = [&] {
    int value = 0;
    if (!binary) {
      value = reader.number();
    } else if (maxval < 256) {
      value = reader.raw();
    } else {
      value = reader.raw() << 8;
      value |= reader.raw();
    }
    if (value > maxval) reader.fail("a sample above maxval");
    return static_cast<std::uint8_t>(value * 255 / maxval);
  };
  image.pixels.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height));
  for (Rgb& pixel : image.pixels) {
    pixel.red = sample();
    pixel.green = sample();
    pixel.blue = sample();
  }
  return image;
}

Scene::Scene(std::vector<Disc> discs, Rgb background) : discs_(std::move(discs)), background_(background) {}

Scene::Scene(RgbImage image) : image_(std::move(image)) {}

Rgb Scene::at(double pan, double tilt) const {
  if (!image_.pixels.empty()) {
    // Pan grows to the left, image columns to the right.
    const auto column = static_cast<long>(std::floor(image_.width / 2.0 - pan / kDegreesPerColumn));
    const auto row = static_cast<long>(std::floor(image_.height / 2.0 - tilt / kDegreesPerRow));
    if (column < 0 || row < 0 || column >= image_.width || row >= image_.height) return {};
    return image_.pixels[static_cast<std::size_t>(row * image_.width + column)];
  }
  for (const Disc& disc : discs_) {
    if (std::hypot(pan - disc.pan, tilt - disc.tilt) <= disc.radius) return disc.color;
  }
  return background_;
}

std::string Scene::describe() const {
  if (!image_.pixels.empty()) {
    return "an image of " + std::to_string(image_.width) + " x " + std::to_string(image_.height) + " pixels";
  }
  return std::to_string(discs_.size()) + " coloured disc" + (discs_.size() == 1 ? "" : "s");
}

hardware::cmucam2::TPacket track(const Scene& scene, const hardware::cmucam2::ColorBounds& bounds, double pan,
                                 double tilt) {
  long count = 0;
  long sum_x = 0;
  long sum_y = 0;
  int left = kFrameWidth;
  int right = -1;
  int top = kFrameHeight;
  int bottom = -1;
  for (int y = 0; y < kFrameHeight; ++y) {
    const double row_tilt = tilt - (y + 0.5 - kFrameHeight / 2.0) * kDegreesPerRow;
    for (int x = 0; x < kFrameWidth; ++x) {
      const Rgb seen = scene.at(pan - (x + 0.5 - kFrameWidth / 2.0) * kDegreesPerColumn, row_tilt);
      if (!bounds.contains(seen.red, seen.green, seen.blue)) continue;
      ++count;
      sum_x += x;
      sum_y += y;
      left = std::min(left, x);
      right = std::max(right, x);
      top = std::min(top, y);
      bottom = std::max(bottom, y);
    }
  }
  if (count == 0) return {};
  const long box = static_cast<long>(right - left + 1) * (bottom - top + 1);
  return {.mx = static_cast<int>(sum_x / count) + 1,
          .my = static_cast<int>(sum_y / count) + 1,
          .x1 = left + 1,
          .y1 = top + 1,
          .x2 = right + 1,
          .y2 = bottom + 1,
          .pixels = static_cast<int>(std::min(255L, (count + 4) / 8)),
          .confidence = static_cast<int>(std::min(255L, count * 255 / box))};
}

}  // namespace playerkit::emulators::cmucam2
