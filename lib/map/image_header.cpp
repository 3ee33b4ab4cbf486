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

}  // namespace

std::optional<ImageSize> image_size_from_header_bytes(std::string_view header) {
  const std::span<const std::uint8_t> bytes(reinterpret_cast<const std::uint8_t*>(header.data()), header.size());
  auto size = image::png_declared_size(bytes);
  if (!size) size = image::pnm_declared_size(bytes);
  if (!size) return std::nullopt;
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
