#include "families/p2os/protocol/aux_serial.hpp"

#include "families/p2os/protocol/errors.hpp"
#include "families/p2os/protocol/test_support.hpp"

#include <gtest/gtest.h>

namespace playerkit::hardware::p2os {
namespace aux_serial_test {

using testing::hex;

const CmucamTracking kBlob{.mx = 40, .my = 70, .x1 = 30, .y1 = 60, .x2 = 49, .y2 = 79,
                           .pixels = 100, .confidence = 128};

std::vector<std::uint8_t> tracking_bytes() {
  const auto message = encode_cmucam_tracking(kBlob);
  return {message.begin(), message.end()};
}

TEST(AuxSerial, TypeThenData) {
  const AuxSerialPacket packet{0xB8, {1, 2, 3}};
  EXPECT_EQ(encode_aux_serial(packet), hex("B8 01 02 03"));
  EXPECT_EQ(decode_aux_serial(hex("B8 01 02 03")), packet);
  EXPECT_EQ(decode_aux_serial(hex("B0")).data.size(), 0u);
  EXPECT_THROW(decode_aux_serial({}), DecodeError);
  EXPECT_THROW(decode_aux_serial(hex("32 00")), DecodeError);
  EXPECT_THROW(encode_aux_serial({0x32, {}}), EncodeError);
}

TEST(CmucamTracking, MessageLayout) {
  EXPECT_EQ(tracking_bytes(), hex("FF 4D 28 46 1E 3C 31 4F 64 80"));
  EXPECT_EQ(kBlob.area(), 20u * 20u * 128u / 255u);
}

TEST(CmucamTracking, RefusesTheStartByteInsideValues) {
  CmucamTracking blob = kBlob;
  blob.confidence = 255;
  EXPECT_THROW(encode_cmucam_tracking(blob), EncodeError);
  EXPECT_THROW(encode_cmucam_color({.red = 255}), EncodeError);
}

TEST(FindCmucamMessage, FindsAMessageAloneOrAfterNoise) {
  EXPECT_EQ(find_cmucam_message(tracking_bytes()), CmucamMessage(kBlob));
  auto noisy = hex("41 42 43 0D");
  const auto message = tracking_bytes();
  noisy.insert(noisy.end(), message.begin(), message.end());
  EXPECT_EQ(find_cmucam_message(noisy), CmucamMessage(kBlob));
}

TEST(FindCmucamMessage, ReadsColourMessages) {
  const auto message = encode_cmucam_color({.red = 200, .green = 10, .blue = 20,
                                            .red_variance = 1, .green_variance = 2,
                                            .blue_variance = 3});
  std::vector<std::uint8_t> data(message.begin(), message.end());
  data.push_back(0x3A);  // the window needs 10 bytes, as the reference's does
  data.push_back(0x0D);
  const auto found = find_cmucam_message(data);
  ASSERT_TRUE(found.has_value());
  EXPECT_EQ(std::get<CmucamColor>(*found).red, 200);
}

TEST(FindCmucamMessage, SearchesOnlyTheReferencesWindow) {
  // Fewer than 10 bytes: nothing.
  const auto message = tracking_bytes();
  EXPECT_EQ(find_cmucam_message(std::span(message).first(9)), std::nullopt);
  // A message ending more than 9 bytes before the end of a long read is
  // outside the window (len − 19 ... len − 10).
  auto data = tracking_bytes();
  data.resize(data.size() + 10, 0x20);
  EXPECT_EQ(data.size(), 20u);
  EXPECT_EQ(find_cmucam_message(data), std::nullopt);
  data.pop_back();  // 19 bytes: start byte at 0 = len − 19, inside again
  EXPECT_EQ(find_cmucam_message(data), CmucamMessage(kBlob));
  // Another letter after the start byte: not understood.
  EXPECT_EQ(find_cmucam_message(hex("FF 41 00 00 00 00 00 00 00 00")), std::nullopt);
}

}  // namespace aux_serial_test
}  // namespace playerkit::hardware::p2os
