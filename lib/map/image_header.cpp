#include "map/image_header.hpp"

#include "image/png.hpp"
#include "image/pnm.hpp"

#include <cstdint>
#include <fstream>
#include <span>
#include <string>

namespace playerkit::map {
namespace {

// Enough for a PNG's IHDR and a PNM header with a few comment lines.
constexpr std::size_t kHeaderBytes = 4096;

// PNG allows 1 to 2^31 - 1 pixels a side, and lib/image's PNM decoder
// refuses what PNG would: a header claiming more (a PNG's u32 fields, a PNM's
// numbers up to 2^32 - 1) is no image either decoder reads. Held to this, a
// side fits in 31 bits and width * height in 62, so callers multiply the two
// without overflow.
constexpr std::int64_t kMaxSide = 0x7fffffff;

bool valid_side(std::int64_t side) { return side >= 1 && side <= kMaxSide; }

}  // namespace

std::optional<ImageSize> image_size_from_header_bytes(std::string_view header) {
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(header.data()), header.size());
  auto size = image::png_declared_size(bytes);
  if (!size) size = image::pnm_declared_size(bytes);
  if (!size || !valid_side(size->width) || !valid_side(size->height)) return std::nullopt;
  return ImageSize{size->width, size->height};
}

std::optional<ImageSize> image_size_from_header(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) return std::nullopt;
  std::string header(kHeaderBytes, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<std::size_t>(in.gcount()));
  return image_size_from_header_bytes(header);
}

}  // namespace playerkit::map
