#pragma once
// Internal: an image's size from its header, read before the image is
// decoded, so that a map image declaring billions of pixels is refused
// without taking the memory (decoding takes a byte per pixel at least).

#include <filesystem>
#include <optional>
#include <string_view>

namespace playerkit::map {

struct ImageSize {
  long long width = 0;
  long long height = 0;
};

// The width and height declared by a PNM (P1-P6: Player's maps) or PNG
// header, as lib/image reads them; nullopt for other formats, a header
// that cannot be read, or a side of 0 or over 2^31 - 1, which no PNG has
// (the decoder then reports those). A size returned has 1 to 2^31 - 1
// pixels a side, so width * height cannot overflow a long long.
std::optional<ImageSize> image_size_from_header_bytes(std::string_view header);
std::optional<ImageSize> image_size_from_header(const std::filesystem::path& file);

}  // namespace playerkit::map
