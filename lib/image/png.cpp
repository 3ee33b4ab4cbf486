#include "image/png.hpp"

#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace playerkit::image {
namespace {

constexpr std::array<std::uint8_t, 8> kSignature{137, 80, 78, 71, 13, 10, 26, 10};

std::uint32_t read_u32(const std::uint8_t* bytes) {
  return (std::uint32_t{bytes[0]} << 24) | (std::uint32_t{bytes[1]} << 16) | (std::uint32_t{bytes[2]} << 8) |
         std::uint32_t{bytes[3]};
}

void append_u32(std::vector<std::uint8_t>& out, std::uint32_t value) {
  out.push_back(static_cast<std::uint8_t>(value >> 24));
  out.push_back(static_cast<std::uint8_t>(value >> 16));
  out.push_back(static_cast<std::uint8_t>(value >> 8));
  out.push_back(static_cast<std::uint8_t>(value));
}

Decoded png_failure(std::string message) {
  Decoded decoded;
  decoded.error = "PNG: " + std::move(message);
  return decoded;
}

struct Header {
  std::uint32_t width = 0, height = 0;
  int bit_depth = 0;
  int colour_type = 0;
  bool interlaced = false;

  int channels() const {
    switch (colour_type) {
      case 2: return 3;
      case 4: return 2;
      case 6: return 4;
      default: return 1;  // grey, palette
    }
  }
  bool valid_depth() const {
    const int d = bit_depth;
    switch (colour_type) {
      case 0: return d == 1 || d == 2 || d == 4 || d == 8 || d == 16;
      case 3: return d == 1 || d == 2 || d == 4 || d == 8;
      case 2: case 4: case 6: return d == 8 || d == 16;
      default: return false;
    }
  }
  // Bytes of one row of `columns` pixels, without the filter byte.
  std::size_t row_bytes(std::size_t columns) const {
    return (columns * static_cast<std::size_t>(channels()) * static_cast<std::size_t>(bit_depth) + 7) / 8;
  }
};

// Where each of Adam7's passes starts and how far apart its pixels are; a
// plain image is the one pass (0, 0, 1, 1).
struct Pass {
  std::size_t column, row, column_step, row_step;
};
constexpr std::array<Pass, 7> kAdam7{{
    {0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2},
}};

std::size_t pass_extent(std::size_t size, std::size_t start, std::size_t step) {
  return size > start ? (size - start + step - 1) / step : 0;
}

std::uint8_t paeth(int left, int above, int upper_left) {
  const int estimate = left + above - upper_left;
  const int to_left = std::abs(estimate - left), to_above = std::abs(estimate - above),
            to_upper_left = std::abs(estimate - upper_left);
  if (to_left <= to_above && to_left <= to_upper_left) return static_cast<std::uint8_t>(left);
  return static_cast<std::uint8_t>(to_above <= to_upper_left ? above : upper_left);
}

// Undoes the filter of one row in place; `above` is the previous row of the
// same pass (zeros for its first).
bool unfilter(int filter, std::uint8_t* row, const std::uint8_t* above, std::size_t length, std::size_t bpp) {
  switch (filter) {
    case 0: return true;
    case 1:
      for (std::size_t i = bpp; i < length; ++i) row[i] = static_cast<std::uint8_t>(row[i] + row[i - bpp]);
      return true;
    case 2:
      for (std::size_t i = 0; i < length; ++i) row[i] = static_cast<std::uint8_t>(row[i] + above[i]);
      return true;
    case 3:
      for (std::size_t i = 0; i < length; ++i) {
        const int left = i >= bpp ? row[i - bpp] : 0;
        row[i] = static_cast<std::uint8_t>(row[i] + ((left + above[i]) >> 1));
      }
      return true;
    case 4:
      for (std::size_t i = 0; i < length; ++i) {
        const int left = i >= bpp ? row[i - bpp] : 0;
        const int upper_left = i >= bpp ? above[i - bpp] : 0;
        row[i] = static_cast<std::uint8_t>(row[i] + paeth(left, above[i], upper_left));
      }
      return true;
    default: return false;
  }
}

// Grey value of pixel `x` of an unfiltered row; false for a palette index
// the palette does not have.
bool grey_at(const Header& header, const std::uint8_t* row, std::size_t x,
             const std::vector<std::array<std::uint8_t, 3>>& palette, std::uint8_t& grey) {
  const int depth = header.bit_depth;
  if (depth < 8) {
    const std::size_t bit = x * static_cast<std::size_t>(depth);
    const unsigned sample =
        (row[bit / 8] >> (8 - depth - static_cast<int>(bit % 8))) & ((1u << depth) - 1u);
    if (header.colour_type == 3) {
      if (sample >= palette.size()) return false;
      grey = grey_of(palette[sample][0], palette[sample][1], palette[sample][2]);
    } else {
      grey = static_cast<std::uint8_t>(sample * (255u / ((1u << depth) - 1u)));
    }
    return true;
  }
  const std::size_t bytes = static_cast<std::size_t>(depth / 8);
  const std::uint8_t* pixel = row + x * static_cast<std::size_t>(header.channels()) * bytes;
  const auto sample = [&](int channel) -> unsigned { return pixel[static_cast<std::size_t>(channel) * bytes]; };
  switch (header.colour_type) {
    case 3:
      if (sample(0) >= palette.size()) return false;
      grey = grey_of(palette[sample(0)][0], palette[sample(0)][1], palette[sample(0)][2]);
      return true;
    case 2: case 6: grey = grey_of(sample(0), sample(1), sample(2)); return true;
    default: grey = static_cast<std::uint8_t>(sample(0)); return true;  // grey, grey + alpha
  }
}

}  // namespace

bool is_png(std::span<const std::uint8_t> bytes) {
  return bytes.size() >= kSignature.size() && std::equal(kSignature.begin(), kSignature.end(), bytes.begin());
}

std::optional<DeclaredSize> png_declared_size(std::span<const std::uint8_t> bytes) {
  // Signature (8), IHDR's length (4) and type (4), then width and height.
  if (!is_png(bytes) || bytes.size() < 24 || !std::equal(bytes.begin() + 12, bytes.begin() + 16, "IHDR")) {
    return std::nullopt;
  }
  return DeclaredSize{read_u32(&bytes[16]), read_u32(&bytes[20])};
}

Decoded decode_png(std::span<const std::uint8_t> bytes) {
  if (!is_png(bytes)) return png_failure("not a PNG file (no signature)");
  Header header;
  bool have_header = false, ended = false;
  std::vector<std::array<std::uint8_t, 3>> palette;
  std::vector<std::uint8_t> compressed;
  std::size_t at = kSignature.size();
  while (!ended) {
    if (bytes.size() - at < 12) return png_failure("the file ends inside a chunk (truncated)");
    const std::uint32_t length = read_u32(&bytes[at]);
    const std::uint8_t* type = &bytes[at + 4];
    const std::string name(reinterpret_cast<const char*>(type), 4);
    if (length > bytes.size() - at - 12) return png_failure("the file ends inside chunk " + name + " (truncated)");
    const std::uint8_t* data = type + 4;
    const std::uint32_t stored_crc = read_u32(data + length);
    const auto crc = static_cast<std::uint32_t>(crc32(crc32(0L, Z_NULL, 0), type, length + 4));
    if (crc != stored_crc) return png_failure("chunk " + name + " is corrupt (its CRC does not match)");
    at += 12 + static_cast<std::size_t>(length);
    if (!have_header && name != "IHDR") return png_failure("the first chunk is " + name + ", not IHDR");
    if (name == "IHDR") {
      if (have_header || length != 13) return png_failure("a bad IHDR chunk");
      header.width = read_u32(data);
      header.height = read_u32(data + 4);
      header.bit_depth = data[8];
      header.colour_type = data[9];
      header.interlaced = data[12] == 1;
      if (data[10] != 0 || data[11] != 0 || data[12] > 1) {
        return png_failure("unknown compression, filter or interlace method");
      }
      if (!header.valid_depth()) {
        return png_failure("colour type " + std::to_string(header.colour_type) + " with " +
                       std::to_string(header.bit_depth) + "-bit samples does not exist");
      }
      if (header.width == 0 || header.height == 0 || header.width > 0x7fffffffu || header.height > 0x7fffffffu ||
          std::int64_t{header.width} * std::int64_t{header.height} > kMaxPixels) {
        return png_failure("an image of " + std::to_string(header.width) + " x " + std::to_string(header.height) +
                       " pixels is empty or too large");
      }
      have_header = true;
    } else if (name == "PLTE") {
      if (length % 3 != 0 || length > 768) return png_failure("a bad PLTE chunk");
      palette.resize(length / 3);
      for (std::size_t i = 0; i < palette.size(); ++i) palette[i] = {data[3 * i], data[3 * i + 1], data[3 * i + 2]};
    } else if (name == "IDAT") {
      compressed.insert(compressed.end(), data, data + length);
    } else if (name == "IEND") {
      ended = true;
    } else if ((type[0] & 0x20) == 0) {
      return png_failure("unknown critical chunk " + name);
    }  // ancillary chunks (text, gamma, transparency, ...) change nothing here
  }
  if (header.colour_type == 3 && palette.empty()) return png_failure("a palette image without a PLTE chunk");
  if (compressed.empty()) return png_failure("no image data (IDAT)");

  const std::size_t width = header.width, height = header.height;
  const std::size_t bpp = std::max<std::size_t>(1, static_cast<std::size_t>(header.channels() * header.bit_depth) / 8);
  const std::size_t passes = header.interlaced ? kAdam7.size() : 1;
  const auto pass_of = [&](std::size_t p) { return header.interlaced ? kAdam7[p] : Pass{0, 0, 1, 1}; };
  std::size_t raw_size = 0;
  for (std::size_t p = 0; p < passes; ++p) {
    const Pass pass = pass_of(p);
    const std::size_t columns = pass_extent(width, pass.column, pass.column_step);
    const std::size_t rows = pass_extent(height, pass.row, pass.row_step);
    if (columns > 0) raw_size += rows * (1 + header.row_bytes(columns));
  }
  std::vector<std::uint8_t> raw(raw_size);
  z_stream stream{};
  if (inflateInit(&stream) != Z_OK) return png_failure("zlib could not start");
  stream.next_in = compressed.data();
  stream.avail_in = static_cast<uInt>(compressed.size());
  stream.next_out = raw.data();
  stream.avail_out = static_cast<uInt>(raw.size());
  const int inflated = inflate(&stream, Z_FINISH);
  const bool filled = stream.avail_out == 0;
  inflateEnd(&stream);
  if (inflated != Z_STREAM_END && !(inflated == Z_BUF_ERROR && filled) && !(inflated == Z_OK && filled)) {
    return png_failure(inflated == Z_DATA_ERROR ? "the image data is corrupt" : "the image data is truncated");
  }
  if (!filled) return png_failure("the image data is truncated");

  Decoded decoded;
  decoded.image.width = static_cast<int>(width);
  decoded.image.height = static_cast<int>(height);
  decoded.image.pixels.assign(width * height, 0);
  std::size_t offset = 0;
  for (std::size_t p = 0; p < passes; ++p) {
    const Pass pass = pass_of(p);
    const std::size_t columns = pass_extent(width, pass.column, pass.column_step);
    const std::size_t rows = pass_extent(height, pass.row, pass.row_step);
    if (columns == 0 || rows == 0) continue;
    const std::size_t length = header.row_bytes(columns);
    std::vector<std::uint8_t> zeros(length, 0);
    const std::uint8_t* above = zeros.data();
    for (std::size_t r = 0; r < rows; ++r) {
      const int filter = raw[offset];
      std::uint8_t* row = &raw[offset + 1];
      if (!unfilter(filter, row, above, length, bpp)) {
        return png_failure("row " + std::to_string(r) + " has unknown filter type " + std::to_string(filter));
      }
      const std::size_t y = pass.row + r * pass.row_step;
      for (std::size_t c = 0; c < columns; ++c) {
        std::uint8_t grey = 0;
        if (!grey_at(header, row, c, palette, grey)) return png_failure("a palette index beyond the palette");
        decoded.image.pixels[y * width + pass.column + c * pass.column_step] = grey;
      }
      above = row;
      offset += 1 + length;
    }
  }
  return decoded;
}

std::vector<std::uint8_t> encode_png(std::span<const std::uint8_t> pixels, int width, int height, int channels) {
  if (channels != 1 && channels != 3) throw std::invalid_argument("encode_png: 1 or 3 channels, not " + std::to_string(channels));
  if (width <= 0 || height <= 0) throw std::invalid_argument("encode_png: an image of no pixels");
  const std::size_t row_length = static_cast<std::size_t>(width) * static_cast<std::size_t>(channels);
  if (pixels.size() != row_length * static_cast<std::size_t>(height)) {
    throw std::invalid_argument("encode_png: " + std::to_string(pixels.size()) + " bytes for " +
                                std::to_string(width) + " x " + std::to_string(height) + " x " +
                                std::to_string(channels));
  }
  // Each row behind filter byte 0 (none): maps and pictures of worlds are
  // mostly runs of one value, which deflate takes well as they are.
  std::vector<std::uint8_t> raw;
  raw.reserve((row_length + 1) * static_cast<std::size_t>(height));
  for (int y = 0; y < height; ++y) {
    raw.push_back(0);
    const auto begin = pixels.begin() + static_cast<std::ptrdiff_t>(row_length * static_cast<std::size_t>(y));
    raw.insert(raw.end(), begin, begin + static_cast<std::ptrdiff_t>(row_length));
  }
  uLongf compressed_size = compressBound(static_cast<uLong>(raw.size()));
  std::vector<std::uint8_t> compressed(compressed_size);
  if (compress2(compressed.data(), &compressed_size, raw.data(), static_cast<uLong>(raw.size()), 6) != Z_OK) {
    throw std::runtime_error("encode_png: zlib could not compress the image");
  }
  compressed.resize(compressed_size);

  std::vector<std::uint8_t> out(kSignature.begin(), kSignature.end());
  const auto chunk = [&out](const char* type, std::span<const std::uint8_t> data) {
    append_u32(out, static_cast<std::uint32_t>(data.size()));
    const std::size_t type_at = out.size();
    out.insert(out.end(), type, type + 4);
    out.insert(out.end(), data.begin(), data.end());
    append_u32(out, static_cast<std::uint32_t>(
                        crc32(crc32(0L, Z_NULL, 0), &out[type_at], static_cast<uInt>(data.size() + 4))));
  };
  std::vector<std::uint8_t> header;
  append_u32(header, static_cast<std::uint32_t>(width));
  append_u32(header, static_cast<std::uint32_t>(height));
  header.insert(header.end(), {8, static_cast<std::uint8_t>(channels == 1 ? 0 : 2), 0, 0, 0});
  chunk("IHDR", header);
  chunk("IDAT", compressed);
  chunk("IEND", {});
  return out;
}

}  // namespace playerkit::image
