#include "map/image_header.hpp"

#include <cctype>
#include <cstdint>
#include <fstream>
#include <string>

namespace playerkit::map {
namespace {

// Enough for a PNG's IHDR and a PNM header with a few comment lines.
constexpr std::size_t kHeaderBytes = 4096;

std::optional<ImageSize> png_size(std::string_view header) {
  // Signature (8), IHDR length (4) and type (4), then width and height, big-endian.
  constexpr std::string_view kSignature = "\x89PNG\r\n\x1a\n";
  if (header.size() < 24 || header.substr(0, 8) != kSignature || header.substr(12, 4) != "IHDR") return std::nullopt;
  const auto big_endian = [&](std::size_t at) {
    std::uint32_t value = 0;
    for (std::size_t i = 0; i < 4; ++i) value = (value << 8) | static_cast<unsigned char>(header[at + i]);
    return static_cast<long long>(value);
  };
  return ImageSize{big_endian(16), big_endian(20)};
}

std::optional<ImageSize> pnm_size(std::string_view header) {
  if (header.size() < 2 || header[0] != 'P' || header[1] < '1' || header[1] > '6') return std::nullopt;
  std::size_t at = 2;
  long long numbers[2] = {0, 0};
  for (long long& number : numbers) {
    // Whitespace and '#' comments to the end of their line may come between fields.
    for (;;) {
      while (at < header.size() && std::isspace(static_cast<unsigned char>(header[at]))) ++at;
      if (at < header.size() && header[at] == '#') {
        while (at < header.size() && header[at] != '\n') ++at;
        continue;
      }
      break;
    }
    if (at >= header.size() || !std::isdigit(static_cast<unsigned char>(header[at]))) return std::nullopt;
    while (at < header.size() && std::isdigit(static_cast<unsigned char>(header[at]))) {
      if (number > 1'000'000'000) return std::nullopt;  // no real header; let the decoder say so
      number = number * 10 + (header[at++] - '0');
    }
  }
  return ImageSize{numbers[0], numbers[1]};
}

}  // namespace

std::optional<ImageSize> image_size_from_header_bytes(std::string_view header) {
  if (auto size = png_size(header)) return size;
  return pnm_size(header);
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
