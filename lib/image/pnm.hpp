#pragma once
// Netpbm images (PBM, PGM, PPM; plain and raw: P1-P6) read into 8-bit grey.
// Samples are scaled from maxval to 0-255, colour becomes grey (grey_of),
// and a PBM's 1 (black) reads 0.

#include "image/grey_image.hpp"

#include <cstdint>
#include <optional>
#include <span>

namespace playerkit::image {

// True when `bytes` start with P1-P6.
bool is_pnm(std::span<const std::uint8_t> bytes);

// The width and height after the magic number (comments allowed): a few
// bytes suffice. nullopt when they cannot be read.
std::optional<DeclaredSize> pnm_declared_size(std::span<const std::uint8_t> bytes);

Decoded decode_pnm(std::span<const std::uint8_t> bytes);

}  // namespace playerkit::image
