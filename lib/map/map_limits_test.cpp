// Map files under hostile input: image sizes checked from the header before
// decoding, regular files only, small YAML, messages escaped.

#include "map/image_header.hpp"
#include "map/map_file.hpp"

#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "support/scratch_directory.hpp"

namespace playerkit::map {
namespace map_limits_test {

using Scratch = playerkit::testing::ScratchDirectory;

std::string error_of(const std::filesystem::path& file, const MapLoadOptions& options = {}) {
  try {
    (void)load_map(file, options);
  } catch (const MapFileError& error) {
    return error.what();
  }
  return "no error";
}

std::string png_header(std::uint32_t width, std::uint32_t height) {
  std::string header("\x89PNG\r\n\x1a\n\0\0\0\x0dIHDR", 16);
  for (const std::uint32_t value : {width, height}) {
    for (int shift = 24; shift >= 0; shift -= 8) header += static_cast<char>((value >> shift) & 0xff);
  }
  return header + std::string("\x08\x00\x00\x00\x00", 5);
}

TEST(ImageHeader, ReadsPnmAndPngSizes) {
  EXPECT_EQ(image_size_from_header_bytes("P5\n640 480\n255\n")->width, 640);
  const auto commented = image_size_from_header_bytes("P2\n# CREATOR: GIMP\n# two lines\n 12\n34 255\n");
  ASSERT_TRUE(commented);
  EXPECT_EQ(commented->width, 12);
  EXPECT_EQ(commented->height, 34);
  const auto png = image_size_from_header_bytes(png_header(100000, 3));
  ASSERT_TRUE(png);
  EXPECT_EQ(png->width, 100000);
  EXPECT_EQ(png->height, 3);
  EXPECT_FALSE(image_size_from_header_bytes("GIF89a"));
  EXPECT_FALSE(image_size_from_header_bytes("P5\nxx"));
}

// Issue 27: sides past PNG's 2^31 - 1 were returned, and width * height of
// 4093640705 x 4093640705 overflowed a long long in every caller.
TEST(ImageHeader, APngSideOfZeroOrPast2To31Minus1IsNoSize) {
  EXPECT_FALSE(image_size_from_header_bytes(png_header(4093640705u, 4093640705u)));
  EXPECT_FALSE(image_size_from_header_bytes(png_header(0xffffffffu, 0xffffffffu)));
  EXPECT_FALSE(image_size_from_header_bytes(png_header(0x80000000u, 1)));
  EXPECT_FALSE(image_size_from_header_bytes(png_header(1, 0x80000000u)));
  EXPECT_FALSE(image_size_from_header_bytes(png_header(0, 5)));
  EXPECT_FALSE(image_size_from_header_bytes(png_header(5, 0)));
  const auto largest = image_size_from_header_bytes(png_header(0x7fffffffu, 0x7fffffffu));
  ASSERT_TRUE(largest);
  EXPECT_EQ(largest->width, 0x7fffffff);
  EXPECT_EQ(largest->height, 0x7fffffff);
}

// A PNM's numbers go to 2^32 - 1: the same bounds as a PNG's.
TEST(ImageHeader, APnmSideOfZeroOrPast2To31Minus1IsNoSize) {
  EXPECT_FALSE(image_size_from_header_bytes("P5\n4294967295 4294967295\n255\n"));
  EXPECT_FALSE(image_size_from_header_bytes("P5\n4093640705 4093640705\n255\n"));
  EXPECT_FALSE(image_size_from_header_bytes("P2\n2147483648 1\n255\n"));
  EXPECT_FALSE(image_size_from_header_bytes("P1\n1 2147483648\n"));
  EXPECT_FALSE(image_size_from_header_bytes("P5\n0 10\n255\n"));
  EXPECT_FALSE(image_size_from_header_bytes("P4\n10 0\n"));
  EXPECT_FALSE(image_size_from_header_bytes("P5\n99999999999999999999 1\n255\n"));
  const auto largest = image_size_from_header_bytes("P5\n2147483647 2147483647\n255\n");
  ASSERT_TRUE(largest);
  EXPECT_EQ(largest->width, 2147483647);
  EXPECT_EQ(largest->height, 2147483647);
}

// load_map leaves such a header to the decoder, which refuses it; before,
// its own size check multiplied the sides (UBSan stopped there).
TEST(MapLimits, AnImageDeclaringSidesNoPngHasIsRefused) {
  Scratch scratch("map_limits_test");
  const auto pgm = scratch.write("huge.pgm", "P5\n4294967295 4294967295\n255\n");
  EXPECT_EQ(error_of(pgm, {.resolution = 0.05}),
            pgm.string() + ": cannot read as an image: PNM: an image of 4294967295 x 4294967295 pixels is empty or too large");
  const auto png = scratch.write("huge.png", png_header(4093640705u, 4093640705u));
  EXPECT_EQ(error_of(png, {.resolution = 0.05}),
            png.string() + ": cannot read as an image: PNG: the file ends inside chunk IHDR (truncated)");
  // At 2^31 - 1 a side the header is read, and the product is refused exactly.
  const auto largest = scratch.write("largest.pgm", "P5\n2147483647 2147483647\n255\n");
  EXPECT_EQ(error_of(largest, {.resolution = 0.05}),
            largest.string() + ": a map of 2147483647 x 2147483647 cells (4611686014132 million) is more than the limit of 50 million");
}

TEST(MapLimits, AnImageDeclaringTooManyPixelsIsRefusedBeforeDecoding) {
  Scratch scratch("map_limits_test");
  // 100000 x 100000 pixels declared in a few bytes: decoding would take 10 GB.
  const auto pgm = scratch.write("huge.pgm", "P5\n100000 100000\n255\n");
  EXPECT_EQ(error_of(pgm, {.resolution = 0.05}),
            pgm.string() + ": a map of 100000 x 100000 cells (10000 million) is more than the limit of 50 million");
  const auto png = scratch.write("huge.png", png_header(60000, 60000));
  EXPECT_EQ(error_of(png, {.resolution = 0.05}),
            png.string() + ": a map of 60000 x 60000 cells (3600 million) is more than the limit of 50 million");
  // Through a YAML too.
  const auto yaml = scratch.write("huge.yaml",
                                  "image: huge.pgm\nresolution: 0.05\norigin: [0, 0, 0]\nnegate: 0\n"
                                  "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  EXPECT_EQ(error_of(yaml), pgm.string() + ": a map of 100000 x 100000 cells (10000 million) is more than the limit of 50 million");
}

TEST(MapLimits, OnlyRegularFilesAreMaps) {
  Scratch scratch("map_limits_test");
  EXPECT_EQ(error_of(scratch.path(), {.resolution = 0.05}), scratch.path().string() + ": it is a directory, not a file");
  EXPECT_EQ(error_of("/dev/zero", {.resolution = 0.05}),
            "/dev/zero: it is not a regular file (a device, a pipe or a socket)");
  const auto directory_yaml = scratch.path() / "dir.yaml";
  std::filesystem::create_directory(directory_yaml);
  EXPECT_EQ(error_of(directory_yaml), directory_yaml.string() + ": it is a directory, not a file");
}

TEST(MapLimits, ALargeYamlIsNotAMapDescription) {
  Scratch scratch("map_limits_test");
  const auto yaml = scratch.write("big.yaml", "# " + std::string(kMaxMapYamlBytes, 'c') + "\n");
  EXPECT_EQ(error_of(yaml), yaml.string() + ": larger than " + std::to_string(kMaxMapYamlBytes) +
                                " bytes: not a map description");
}

TEST(MapLimits, QuotedValuesAreEscapedAndCut) {
  Scratch scratch("map_limits_test");
  const auto yaml = scratch.write("bad.yaml", "image: a.pgm\nresolution: \x1b[2J" + std::string(300, '9') +
                                                  "\norigin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const std::string error = error_of(yaml);
  EXPECT_EQ(error.find('\x1b'), std::string::npos) << error;
  EXPECT_NE(error.find("resolution must be a number, got '\\x1b[2J" + std::string(73, '9') + "\u2026'"), std::string::npos)
      << error;
}

}  // namespace map_limits_test
}  // namespace playerkit::map
