#pragma once
// Player 1.5 `camera` payloads: constants and packed structs, field for field
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

inline constexpr std::size_t kCameraImageWidth = 640;  // maximum image width
inline constexpr std::size_t kCameraImageHeight = 480;  // maximum image height
inline constexpr std::size_t kCameraImageSize = 1228800;  // image buffer bytes (640*480*4); far above MAX_MESSAGE_SIZE

// Only the image bytes in use travel: the full struct (1228809 bytes) is far above the 8192-byte message limit.
struct CameraData {
  static constexpr std::string_view kWireName = "player_camera_data_t";
  static constexpr std::size_t kWireSize = 1228809;

  std::uint16_t width = 0;  // image width, pixels
  std::uint16_t height = 0;  // image height, pixels
  std::uint8_t depth = 0;  // bits per pixel (8, 16, 24)
  std::uint32_t image_size = 0;  // bytes of image data used
  std::vector<std::uint8_t> image{};  // packed pixel data

  static constexpr auto fields() {
    return std::tuple{field("width", &CameraData::width),
                      field("height", &CameraData::height),
                      field("depth", &CameraData::depth),
                      field("image_size", &CameraData::image_size),
                      sized_tail("image", &CameraData::image, &CameraData::image_size, 1228800, kCameraImageSize)};
  }
  friend bool operator==(const CameraData&, const CameraData&) = default;
};

}  // namespace playerkit::protocol
