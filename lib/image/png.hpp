#pragma once
// PNG (ISO/IEC 15948) read into 8-bit grey and written from grey or RGB.
//
// Reading takes every standard PNG: grey, RGB, palette, with or without
// alpha, 1 to 16 bits, interlaced or not. Colour becomes grey (grey_of),
// alpha is dropped, 16-bit samples keep their high byte, 1-4-bit grey is
// scaled to 0-255: what OpenCV's imread(IMREAD_GRAYSCALE) gave.

#include "image/grey_image.hpp"

#include <cstdint>
#include <optional>
#include <span>
#include <vector>

namespace playerkit::image {

// True when `bytes` start with the PNG signature.
bool is_png(std::span<const std::uint8_t> bytes);

// The size in the IHDR chunk: the first 24 bytes suffice. nullopt when
// they are not a PNG's.
std::optional<DeclaredSize> png_declared_size(std::span<const std::uint8_t> bytes);

Decoded decode_png(std::span<const std::uint8_t> bytes);

// 8-bit pixels, row-major from the top; `channels` 1 (grey) or 3 (R, G, B).
// Throws std::invalid_argument for other channel counts, a size that does
// not match, or an image of no pixels.
std::vector<std::uint8_t> encode_png(std::span<const std::uint8_t> pixels, int width, int height,
                                     int channels);

}  // namespace playerkit::image
