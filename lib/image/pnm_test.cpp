#include "image/pnm.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include <string>

namespace playerkit::image {
namespace pnm_test {

std::vector<std::uint8_t> bytes_of(const std::string& text) { return {text.begin(), text.end()}; }

Decoded decode(const std::string& text) { return decode_pnm(bytes_of(text)); }

TEST(DecodePnm, RawGreyAsOpenCvReadsIt) {
  cv::Mat grey(23, 31, CV_8UC1);
  for (int y = 0; y < grey.rows; ++y) {
    for (int x = 0; x < grey.cols; ++x) grey.at<std::uint8_t>(y, x) = static_cast<std::uint8_t>(x * 8 + y);
  }
  std::vector<std::uint8_t> bytes;
  ASSERT_TRUE(cv::imencode(".pgm", grey, bytes));
  const Decoded decoded = decode_pnm(bytes);
  ASSERT_TRUE(decoded.ok()) << decoded.error;
  ASSERT_EQ(decoded.image.width, 31);
  ASSERT_EQ(decoded.image.height, 23);
  for (int y = 0; y < grey.rows; ++y) {
    for (int x = 0; x < grey.cols; ++x) {
      ASSERT_EQ(decoded.image.pixels[static_cast<std::size_t>(y * 31 + x)], grey.at<std::uint8_t>(y, x));
    }
  }
}

TEST(DecodePnm, PlainAndRawOfEveryKindWithCommentsAndMaxval) {
  // Player's own maps: a comment after the magic number, maxval 255.
  Decoded d = decode(std::string("P5\n# CREATOR: GIMP\n3 1\n255\n") + std::string("\x00\x80\xff", 3));
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_EQ(d.image.pixels, (std::vector<std::uint8_t>{0, 128, 255}));

  d = decode("P2 3 2 # a comment\n 15\n0 15 7\n1 2 3\n");
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_EQ(d.image.pixels, (std::vector<std::uint8_t>{0, 255, 119, 17, 34, 51}));

  d = decode(std::string("P5 2 1 65535\n") + std::string("\xff\xff\x80\x00", 4));  // 16-bit, big-endian
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_EQ(d.image.pixels, (std::vector<std::uint8_t>{255, 128}));

  d = decode("P1\n4 2\n1 0 1 0\n0011\n");  // 1 is black; plain bits need no spaces
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_EQ(d.image.pixels, (std::vector<std::uint8_t>{0, 255, 0, 255, 255, 255, 0, 0}));

  d = decode(std::string("P4 10 1\n") + std::string("\xa0\x40", 2));  // rows padded to whole bytes
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_EQ(d.image.pixels, (std::vector<std::uint8_t>{0, 255, 0, 255, 255, 255, 255, 255, 255, 0}));

  d = decode("P3 2 1 255\n255 0 0  0 0 255\n");
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_EQ(d.image.pixels, (std::vector<std::uint8_t>{grey_of(255, 0, 0), grey_of(0, 0, 255)}));
  d = decode(std::string("P6 1 1 255\n") + std::string("\x00\xff\x00", 3));
  ASSERT_TRUE(d.ok()) << d.error;
  EXPECT_EQ(d.image.pixels, (std::vector<std::uint8_t>{grey_of(0, 255, 0)}));
}

TEST(DecodePnm, DamagedFilesGetAnError) {
  EXPECT_NE(decode("P5 4 4 255\nabc").error.find("truncated"), std::string::npos);
  EXPECT_NE(decode("P2 2 2 255\n1 2 3").error.find("truncated"), std::string::npos);
  EXPECT_NE(decode("P5 4 x 255\n").error.find("bad header"), std::string::npos);
  EXPECT_NE(decode("P5 0 4 255\n").error.find("empty or too large"), std::string::npos);
  EXPECT_NE(decode("P5 100000 100000 255\n").error.find("too large"), std::string::npos);
  // Sides whose product overflows an int64 (UBSan stopped here; issue 27's PNM twin).
  EXPECT_NE(decode("P5 4294967295 4294967295 255\n").error.find("4294967295 x 4294967295 pixels is empty or too large"),
            std::string::npos);
  EXPECT_NE(decode("P5 2147483648 1 255\n").error.find("too large"), std::string::npos);
  EXPECT_NE(decode("P5 1 1 70000\n").error.find("maxval"), std::string::npos);
  EXPECT_NE(decode("P7 1 1 255\n").error.find("not a PBM"), std::string::npos);
  EXPECT_FALSE(is_pnm(bytes_of("GIF89a")));
}

TEST(PnmDeclaredSize, ReadsWidthAndHeightPastComments) {
  const auto size = pnm_declared_size(bytes_of("P2\n# CREATOR: GIMP\n 12\n34"));
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 12);
  EXPECT_EQ(size->height, 34);
  EXPECT_EQ(pnm_declared_size(bytes_of("P5 100000 100000"))->width, 100000);  // no pixels needed
  EXPECT_FALSE(pnm_declared_size(bytes_of("P5\nxx")));
  EXPECT_FALSE(pnm_declared_size(bytes_of("GIF89a")));
}

}  // namespace pnm_test
}  // namespace playerkit::image
