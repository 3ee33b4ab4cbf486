#pragma once
// The Flock of Birds' POSITION/ANGLES record (flockofbirds.md §1.1): six
// 16-bit two's-complement words, X Y Z azimuth elevation roll, each sent LS
// byte first with 7 data bits a byte; bit 7 (the phasing bit) is set on the
// record's first byte only. The two lowest bits of every word never travel.
//
// Full scale is the manufacturer's W / 32768: of the position scaling
// (36" = 914.4 mm or 72" = 1828.8 mm) for X Y Z, of 180 degrees for angles.
// Worked example of the sheet (36"): X 12", Y -6", Z 3", az 90, el -45,
// roll 10 -> AA 15 2A 75 2A 05 00 20 00 70 47 03.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>

#include "framing/phasing_bit_format.hpp"

namespace playerkit::hardware::flockofbirds {

inline constexpr std::size_t kRecordSize = 12;
inline constexpr std::uint8_t kPhasingBit = 0x80;

// Parameter 3, POSITION SCALING: what full scale of a position word means.
enum class PositionScaling { inches_36, inches_72 };

[[nodiscard]] double full_scale_mm(PositionScaling scaling);  // 914.4 or 1828.8
[[nodiscard]] int full_scale_inches(PositionScaling scaling);  // 36 or 72

// A pose as the bird measures it, in its own frame: millimetres and degrees
// (azimuth about Z, elevation about Y, roll about X; -180 to 180).
struct BirdPose {
  double x_mm = 0;
  double y_mm = 0;
  double z_mm = 0;
  double azimuth_deg = 0;
  double elevation_deg = 0;
  double roll_deg = 0;
  friend bool operator==(const BirdPose&, const BirdPose&) = default;
};

using RecordWords = std::array<std::int16_t, 6>;
using Record = std::array<std::uint8_t, kRecordSize>;

// One word's two bytes, phasing bit clear on both.
[[nodiscard]] std::array<std::uint8_t, 2> encode_word(std::int16_t word);
// The word the two bytes carry (bits 0-1 zero); the phasing bit is ignored.
[[nodiscard]] std::int16_t decode_word(std::uint8_t ls, std::uint8_t ms);

[[nodiscard]] Record encode_record(const RecordWords& words);
// nullopt unless `bytes` is one record: 12 bytes, the phasing bit on the
// first and on no other.
[[nodiscard]] std::optional<RecordWords> decode_record(std::span<const std::uint8_t> bytes);

// Physical values <-> words: rounded to the nearest word and clamped to
// int16 (a position beyond full scale reads as full scale, as on the bird).
[[nodiscard]] RecordWords words_from_pose(const BirdPose& pose, PositionScaling scaling);
[[nodiscard]] BirdPose pose_from_words(const RecordWords& words, PositionScaling scaling);

// Records cut from a byte stream on their phasing bit.
[[nodiscard]] framing::PhasingBitOptions record_format_options();

}  // namespace playerkit::hardware::flockofbirds
