// Golden-byte tests of the `camera` interface (wire-format.md §5 "camera", §7: the
// 1 228 809-byte struct is never sent whole; only the image bytes in use travel).

#include "protocol/messages/camera.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace camera_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;

static_assert(CameraData::kWireSize == 1228809);  // player_camera_data_t: 9 + 1228800
static_assert(kCameraImageSize == 1228800);

const CameraData kSixPixels{.width = 0x0102,
                            .height = 0x0304,
                            .depth = 24,
                            .image_size = 6,
                            .image = {0xA1, 0xA2, 0xA3, 0xA4, 0xA5, 0xA6}};
const Bytes kSixPixelsBytes{0x01, 0x02,              // width      @0 uint16
                            0x03, 0x04,              // height     @2 uint16
                            0x18,                    // depth      @4 uint8 = 24 bits per pixel
                            0x00, 0x00, 0x00, 0x06,  // image_size @5 uint32 = 6
                            0xA1, 0xA2, 0xA3,        // image      @9 uint8[], only the bytes in use
                            0xA4, 0xA5, 0xA6};

TEST(CameraGolden, DataCarriesOnlyTheImageBytesInUse) {
  EXPECT_TRUE(EncodesTo(kSixPixels, kSixPixelsBytes));
  EXPECT_TRUE(DecodesTo(kSixPixelsBytes, kSixPixels));
}

TEST(CameraGolden, DataJson) {
  const auto j = to_json(kSixPixels);
  EXPECT_TRUE(golden::HasFields(j, {"width", "height", "depth", "image_size", "image"}));
  EXPECT_EQ(j.at("depth"), 24);
  EXPECT_EQ(j.at("image_size"), 6);
  EXPECT_EQ(j.at("image"), (nlohmann::json{0xA1, 0xA2, 0xA3, 0xA4, 0xA5, 0xA6}));
  EXPECT_TRUE(SurvivesJson(kSixPixels));
}

TEST(CameraGolden, EmptyImageIsNineBytes) {
  const CameraData empty{.width = 0x0102, .height = 0x0304, .depth = 8, .image_size = 0, .image = {}};
  const Bytes golden_bytes{0x01, 0x02, 0x03, 0x04, 0x08, 0x00, 0x00, 0x00, 0x00};
  EXPECT_TRUE(EncodesTo(empty, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, empty));
}

TEST(CameraGolden, TruncatedHeaderOrOversizedImageIsRejected) {
  EXPECT_TRUE(Rejects<CameraData>(Bytes(kSixPixelsBytes.begin(), kSixPixelsBytes.begin() + 8), "image_size", 9, 8));
  EXPECT_TRUE(Rejects<CameraData>(golden::kEmpty, "width", 9, 0));
  Bytes full(9 + 1228800, 0);
  EXPECT_TRUE(golden::Accepts<CameraData>(full));
  full.push_back(0);
  EXPECT_TRUE(Rejects<CameraData>(full, "", 1228809, 1228810));
}

// image_size counts the bytes of image[] in use; the codec promises that a decoded
// value never claims more elements than it holds.
TEST(CameraGolden, ImageSizeLargerThanTheImageBytesPresentIsRejected) {
  Bytes bytes = kSixPixelsBytes;
  bytes[8] = 0x07;  // image_size @5 = 7, but only 6 image bytes follow
  EXPECT_THROW((void)decode<CameraData>(bytes), DecodeError);
}

}  // namespace camera_test
}  // namespace playerkit::protocol
