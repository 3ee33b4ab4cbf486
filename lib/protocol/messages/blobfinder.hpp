#pragma once
// Player 1.5 `blobfinder` payloads: constants and packed structs, field for field
// as in wire-format.md §5 (names, order, sizes). Values are in wire units.

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <vector>

#include "protocol/fields.hpp"
#include "protocol/fixed_string.hpp"
#include "protocol/constants.hpp"

namespace playerkit::protocol {

inline constexpr std::uint8_t kBlobfinderSetColorReq = 1;  // set tracked colour range
inline constexpr std::uint8_t kBlobfinderSetImagerParamsReq = 2;  // set camera parameters
inline constexpr std::size_t kBlobfinderMaxChannels = 32;  // number of colour channels in the header array
inline constexpr std::size_t kBlobfinderMaxBlobsPerChannel = 10;  // nominal per-channel blob limit
inline constexpr std::size_t kBlobfinderMaxBlobs = 320;  // capacity of blobs[] (macro is not parenthesised: expands to 32 * 10)
inline constexpr std::size_t kBlobfinderHeaderSize = 132;  // bytes before blobs[]: 2+2+32*4
inline constexpr std::size_t kBlobfinderBlobSize = 22;  // size of one blob entry

struct BlobfinderChannel {
  static constexpr std::string_view kWireName = "player_blobfinder_header_elt_t";
  static constexpr std::size_t kWireSize = 4;

  std::uint16_t index = 0;  // offset of first blob of this channel in blobs[]
  std::uint16_t num = 0;  // number of blobs in this channel

  static constexpr auto fields() {
    return std::tuple{field("index", &BlobfinderChannel::index),
                      field("num", &BlobfinderChannel::num)};
  }
  friend bool operator==(const BlobfinderChannel&, const BlobfinderChannel&) = default;
};

struct BlobfinderBlob {
  static constexpr std::string_view kWireName = "player_blobfinder_blob_elt_t";
  static constexpr std::size_t kWireSize = 22;

  std::uint32_t color = 0;  // descriptive colour, packed 0x00RRGGBB
  std::uint32_t area = 0;  // area, pixels
  std::uint16_t x = 0;  // centroid x, pixels
  std::uint16_t y = 0;  // centroid y, pixels
  std::uint16_t left = 0;  // bounding box left, pixels
  std::uint16_t right = 0;  // bounding box right
  std::uint16_t top = 0;  // bounding box top
  std::uint16_t bottom = 0;  // bounding box bottom
  std::uint16_t range = 0;  // range to blob, mm

  static constexpr auto fields() {
    return std::tuple{field("color", &BlobfinderBlob::color),
                      field("area", &BlobfinderBlob::area),
                      field("x", &BlobfinderBlob::x),
                      field("y", &BlobfinderBlob::y),
                      field("left", &BlobfinderBlob::left),
                      field("right", &BlobfinderBlob::right),
                      field("top", &BlobfinderBlob::top),
                      field("bottom", &BlobfinderBlob::bottom),
                      field("range", &BlobfinderBlob::range)};
  }
  friend bool operator==(const BlobfinderBlob&, const BlobfinderBlob&) = default;
};

// Drivers send only the blobs they found: 132 + 22 * n bytes (wire-format.md §6).
struct BlobfinderData {
  static constexpr std::string_view kWireName = "player_blobfinder_data_t";
  static constexpr std::size_t kWireSize = 7172;

  std::uint16_t width = 0;  // image width, pixels
  std::uint16_t height = 0;  // image height, pixels
  std::array<BlobfinderChannel, 32> header{};  // per-channel index (4 bytes each)
  std::vector<BlobfinderBlob> blobs{};  // blob list (22 bytes each); only the used prefix is usually sent

  static constexpr auto fields() {
    return std::tuple{field("width", &BlobfinderData::width),
                      field("height", &BlobfinderData::height),
                      field("header", &BlobfinderData::header),
                      tail("blobs", &BlobfinderData::blobs, 320, kBlobfinderMaxBlobs)};
  }
  friend bool operator==(const BlobfinderData&, const BlobfinderData&) = default;
};

struct BlobfinderColorConfig {
  static constexpr std::string_view kWireName = "player_blobfinder_color_config_t";
  static constexpr std::size_t kWireSize = 13;

  std::uint8_t subtype = 0;  // PLAYER_BLOBFINDER_SET_COLOR_REQ (1)
  std::int16_t rmin = 0;  // red minimum 0-255 (-1 = auto)
  std::int16_t rmax = 0;  // red maximum
  std::int16_t gmin = 0;  // green minimum
  std::int16_t gmax = 0;  // green maximum
  std::int16_t bmin = 0;  // blue minimum
  std::int16_t bmax = 0;  // blue maximum

  static constexpr auto fields() {
    return std::tuple{field("subtype", &BlobfinderColorConfig::subtype),
                      field("rmin", &BlobfinderColorConfig::rmin),
                      field("rmax", &BlobfinderColorConfig::rmax),
                      field("gmin", &BlobfinderColorConfig::gmin),
                      field("gmax", &BlobfinderColorConfig::gmax),
                      field("bmin", &BlobfinderColorConfig::bmin),
                      field("bmax", &BlobfinderColorConfig::bmax)};
  }
  friend bool operator==(const BlobfinderColorConfig&, const BlobfinderColorConfig&) = default;
};

struct BlobfinderImagerConfig {
  static constexpr std::string_view kWireName = "player_blobfinder_imager_config_t";
  static constexpr std::size_t kWireSize = 7;

  std::uint8_t subtype = 0;  // PLAYER_BLOBFINDER_SET_IMAGER_PARAMS_REQ (2)
  std::int16_t brightness = 0;  // 0-255, -1 = unchanged
  std::int16_t contrast = 0;  // 0-255, -1 = unchanged
  std::int8_t colormode = 0;  // 0..3 (RGB/YCrCb x AWB off/on), -1 = unchanged
  std::int8_t autogain = 0;  // 0 off, 1 on, -1 unchanged

  static constexpr auto fields() {
    return std::tuple{field("subtype", &BlobfinderImagerConfig::subtype),
                      field("brightness", &BlobfinderImagerConfig::brightness),
                      field("contrast", &BlobfinderImagerConfig::contrast),
                      field("colormode", &BlobfinderImagerConfig::colormode),
                      field("autogain", &BlobfinderImagerConfig::autogain)};
  }
  friend bool operator==(const BlobfinderImagerConfig&, const BlobfinderImagerConfig&) = default;
};

}  // namespace playerkit::protocol
