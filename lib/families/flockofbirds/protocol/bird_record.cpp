#include "families/flockofbirds/protocol/bird_record.hpp"

#include <algorithm>
#include <cmath>

namespace playerkit::hardware::flockofbirds {

namespace {

constexpr double kWordFullScale = 32768.0;
constexpr double kAngleFullScaleDeg = 180.0;

std::int16_t word_from(double value, double full_scale) {
  if (!std::isfinite(value)) return 0;
  const double scaled = std::round(value / full_scale * kWordFullScale);
  return static_cast<std::int16_t>(std::clamp(scaled, -32768.0, 32767.0));
}

double value_from(std::int16_t word, double full_scale) { return word * full_scale / kWordFullScale; }

}  // namespace

double full_scale_mm(PositionScaling scaling) { return scaling == PositionScaling::inches_36 ? 914.4 : 1828.8; }
int full_scale_inches(PositionScaling scaling) { return scaling == PositionScaling::inches_36 ? 36 : 72; }

std::array<std::uint8_t, 2> encode_word(std::int16_t word) {
  const auto bits = static_cast<std::uint16_t>(word);
  return {static_cast<std::uint8_t>((bits >> 2) & 0x7F), static_cast<std::uint8_t>((bits >> 9) & 0x7F)};
}

std::int16_t decode_word(std::uint8_t ls, std::uint8_t ms) {
  const auto bits = static_cast<std::uint16_t>(((ls & 0x7F) << 2) | ((ms & 0x7F) << 9));
  return static_cast<std::int16_t>(bits);
}

Record encode_record(const RecordWords& words) {
  Record record{};
  for (std::size_t i = 0; i < words.size(); ++i) {
    const auto [ls, ms] = encode_word(words[i]);
    record[2 * i] = ls;
    record[2 * i + 1] = ms;
  }
  record[0] |= kPhasingBit;
  return record;
}

std::optional<RecordWords> decode_record(std::span<const std::uint8_t> bytes) {
  if (bytes.size() != kRecordSize || (bytes[0] & kPhasingBit) == 0) return std::nullopt;
  if (std::any_of(bytes.begin() + 1, bytes.end(), [](std::uint8_t b) { return (b & kPhasingBit) != 0; })) {
    return std::nullopt;
  }
  RecordWords words{};
  for (std::size_t i = 0; i < words.size(); ++i) words[i] = decode_word(bytes[2 * i], bytes[2 * i + 1]);
  return words;
}

RecordWords words_from_pose(const BirdPose& pose, PositionScaling scaling) {
  const double range = full_scale_mm(scaling);
  return {word_from(pose.x_mm, range),
          word_from(pose.y_mm, range),
          word_from(pose.z_mm, range),
          word_from(pose.azimuth_deg, kAngleFullScaleDeg),
          word_from(pose.elevation_deg, kAngleFullScaleDeg),
          word_from(pose.roll_deg, kAngleFullScaleDeg)};
}

BirdPose pose_from_words(const RecordWords& words, PositionScaling scaling) {
  const double range = full_scale_mm(scaling);
  return {.x_mm = value_from(words[0], range),
          .y_mm = value_from(words[1], range),
          .z_mm = value_from(words[2], range),
          .azimuth_deg = value_from(words[3], kAngleFullScaleDeg),
          .elevation_deg = value_from(words[4], kAngleFullScaleDeg),
          .roll_deg = value_from(words[5], kAngleFullScaleDeg)};
}

framing::PhasingBitOptions record_format_options() {
  return {.record_size = kRecordSize, .phasing_mask = kPhasingBit, .name = "flockofbirds"};
}

}  // namespace playerkit::hardware::flockofbirds
