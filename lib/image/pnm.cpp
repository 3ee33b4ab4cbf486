#include "image/pnm.hpp"

#include <cctype>
#include <string>

namespace playerkit::image {
namespace {

Decoded pnm_failure(std::string message) {
  Decoded decoded;
  decoded.error = "PNM: " + std::move(message);
  return decoded;
}

// Reads the header's and a plain file's numbers: whitespace and comments
// (# to the end of the line) between them.
class Reader {
 public:
  explicit Reader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}

  bool number(std::uint32_t& value) {
    skip_space();
    if (at_ >= bytes_.size() || !std::isdigit(bytes_[at_])) return false;
    std::uint64_t n = 0;
    while (at_ < bytes_.size() && std::isdigit(bytes_[at_])) {
      n = n * 10 + (bytes_[at_++] - '0');
      if (n > 0xffffffffu) return false;
    }
    value = static_cast<std::uint32_t>(n);
    return true;
  }
  // A plain PBM's pixels need no space between them.
  bool bit(std::uint32_t& value) {
    skip_space();
    if (at_ >= bytes_.size() || (bytes_[at_] != '0' && bytes_[at_] != '1')) return false;
    value = bytes_[at_++] - '0';
    return true;
  }
  // After the header's last number comes exactly one whitespace byte.
  bool raw_start() {
    if (at_ >= bytes_.size() || !std::isspace(bytes_[at_])) return false;
    ++at_;
    return true;
  }
  std::size_t position() const { return at_; }

 private:
  void skip_space() {
    while (at_ < bytes_.size()) {
      if (bytes_[at_] == '#') {
        while (at_ < bytes_.size() && bytes_[at_] != '\n' && bytes_[at_] != '\r') ++at_;
      } else if (std::isspace(bytes_[at_])) {
        ++at_;
      } else {
        break;
      }
    }
  }
  std::span<const std::uint8_t> bytes_;
  std::size_t at_ = 2;  // past the magic number
};

}  // namespace

bool is_pnm(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= 2 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '6';
}

std::optional<DeclaredSize> pnm_declared_size(std::span<const std::uint8_t> bytes) {
  if (!is_pnm(bytes)) return std::nullopt;
  Reader reader(bytes);
  std::uint32_t width = 0, height = 0;
  if (!reader.number(width) || !reader.number(height)) return std::nullopt;
  return DeclaredSize{width, height};
}

Decoded decode_pnm(std::span<const std::uint8_t> bytes) {
  if (!is_pnm(bytes)) return pnm_failure("not a PBM, PGM or PPM file (no P1-P6)");
  const int kind = bytes[1] - '0';
  const bool bitmap = kind == 1 || kind == 4, colour = kind == 3 || kind == 6, plain = kind <= 3;
  Reader reader(bytes);
  std::uint32_t width = 0, height = 0, maxval = 1;
  if (!reader.number(width) || !reader.number(height) || (!bitmap && !reader.number(maxval))) {
    return pnm_failure("a bad header (width, height" + std::string(bitmap ? "" : ", maxval") + " expected)");
  }
  // The sides before their product: two of up to 2^32 - 1 overflow an int64.
  if (width == 0 || height == 0 || width > 0x7fffffffu || height > 0x7fffffffu ||
      std::int64_t{width} * std::int64_t{height} > kMaxPixels) {
    return pnm_failure("an image of " + std::to_string(width) + " x " + std::to_string(height) +
                   " pixels is empty or too large");
  }
  if (maxval == 0 || maxval > 65535) return pnm_failure("maxval " + std::to_string(maxval) + " is not 1-65535");

  Decoded decoded;
  decoded.image.width = static_cast<int>(width);
  decoded.image.height = static_cast<int>(height);
  const std::size_t count = std::size_t{width} * std::size_t{height};
  decoded.image.pixels.resize(count);
  const auto scale = [maxval](std::uint32_t sample) {
    return static_cast<std::uint8_t>((std::min(sample, maxval) * 255u + maxval / 2) / maxval);
  };
  const int samples_per_pixel = colour ? 3 : 1;

  if (plain) {
    for (std::size_t i = 0; i < count; ++i) {
      std::uint32_t s[3] = {0, 0, 0};
      for (int c = 0; c < samples_per_pixel; ++c) {
        if (!(bitmap ? reader.bit(s[c]) : reader.number(s[c]))) {
          return pnm_failure("the pixels end after " + std::to_string(i) + " of " + std::to_string(count) + " (truncated)");
        }
      }
      decoded.image.pixels[i] = bitmap ? static_cast<std::uint8_t>(s[0] ? 0 : 255)
                                : colour ? grey_of(scale(s[0]), scale(s[1]), scale(s[2]))
                                         : scale(s[0]);
    }
    return decoded;
  }

  if (!reader.raw_start()) return pnm_failure("no whitespace between the header and the pixels");
  const std::size_t start = reader.position();
  const std::size_t sample_bytes = maxval > 255 ? 2 : 1;
  const std::size_t row_bytes = bitmap ? (std::size_t{width} + 7) / 8
                                       : std::size_t{width} * static_cast<std::size_t>(samples_per_pixel) * sample_bytes;
  const std::size_t needed = row_bytes * std::size_t{height};
  if (bytes.size() - start < needed) {
    return pnm_failure("the pixels are truncated (" + std::to_string(bytes.size() - start) + " of " +
                   std::to_string(needed) + " bytes)");
  }
  const std::uint8_t* data = bytes.data() + start;
  for (std::size_t y = 0; y < height; ++y) {
    const std::uint8_t* row = data + y * row_bytes;
    for (std::size_t x = 0; x < width; ++x) {
      std::uint8_t& out = decoded.image.pixels[y * width + x];
      if (bitmap) {
        out = (row[x / 8] >> (7 - x % 8)) & 1u ? 0 : 255;
        continue;
      }
      const auto sample = [&](int c) -> std::uint32_t {
        const std::uint8_t* s = row + (x * static_cast<std::size_t>(samples_per_pixel) + static_cast<std::size_t>(c)) * sample_bytes;
        return sample_bytes == 2 ? (std::uint32_t{s[0]} << 8 | s[1]) : s[0];
      };
      out = colour ? grey_of(scale(sample(0)), scale(sample(1)), scale(sample(2))) : scale(sample(0));
    }
  }
  return decoded;
}

}  // namespace playerkit::image
