#include "image/png.hpp"

#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdlib>
#include <cstring>
#include <random>

namespace playerkit::image {
namespace png_test {

// What OpenCV's imread(IMREAD_GRAYSCALE) makes of the same bytes.
cv::Mat opencv_grey(const std::vector<std::uint8_t>& bytes) {
  return cv::imdecode(cv::Mat(1, static_cast<int>(bytes.size()), CV_8UC1, const_cast<std::uint8_t*>(bytes.data())),
                      cv::IMREAD_GRAYSCALE);
}

// Equal to OpenCV's reading, pixel for pixel; colour conversions may round
// one level apart.
void expect_like_opencv(const std::vector<std::uint8_t>& bytes, int tolerance = 0) {
  const Decoded decoded = decode_png(bytes);
  ASSERT_TRUE(decoded.ok()) << decoded.error;
  const cv::Mat reference = opencv_grey(bytes);
  ASSERT_EQ(reference.type(), CV_8UC1);
  ASSERT_EQ(decoded.image.width, reference.cols);
  ASSERT_EQ(decoded.image.height, reference.rows);
  int worst = 0;
  for (int y = 0; y < reference.rows; ++y) {
    for (int x = 0; x < reference.cols; ++x) {
      const int ours = decoded.image.pixels[static_cast<std::size_t>(y * reference.cols + x)];
      worst = std::max(worst, std::abs(ours - reference.at<std::uint8_t>(y, x)));
    }
  }
  EXPECT_LE(worst, tolerance);
}

// A test picture: gradients and noise, so every filter type gets used when
// OpenCV's libpng picks filters per row.
cv::Mat picture(int type, int width = 61, int height = 37) {
  cv::Mat image(height, width, type);
  std::mt19937 rng(7);
  const int channels = image.channels();
  const bool deep = image.depth() == CV_16U;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      for (int c = 0; c < channels; ++c) {
        const unsigned value = (x * 7 + y * 3 + c * 50 + (rng() % 9)) % 256;
        if (deep) {
          image.ptr<std::uint16_t>(y)[x * channels + c] = static_cast<std::uint16_t>(value * 257 + rng() % 200);
        } else {
          image.ptr<std::uint8_t>(y)[x * channels + c] = static_cast<std::uint8_t>(value);
        }
      }
    }
  }
  return image;
}

std::vector<std::uint8_t> opencv_png(const cv::Mat& image, std::vector<int> parameters = {}) {
  std::vector<std::uint8_t> bytes;
  EXPECT_TRUE(cv::imencode(".png", image, bytes, parameters));
  return bytes;
}

TEST(DecodePng, ReadsWhatOpenCvWritesAsOpenCvReadsIt) {
  expect_like_opencv(opencv_png(picture(CV_8UC1)));
  expect_like_opencv(opencv_png(picture(CV_16UC1)));
  expect_like_opencv(opencv_png(picture(CV_8UC3)), 1);
  expect_like_opencv(opencv_png(picture(CV_8UC4)), 1);   // alpha dropped
  expect_like_opencv(opencv_png(picture(CV_16UC3)), 1);
  expect_like_opencv(opencv_png(picture(CV_8UC1), {cv::IMWRITE_PNG_BILEVEL, 1}));  // 1-bit grey
  for (int strategy : {cv::IMWRITE_PNG_STRATEGY_FILTERED, cv::IMWRITE_PNG_STRATEGY_RLE}) {
    expect_like_opencv(opencv_png(picture(CV_8UC1), {cv::IMWRITE_PNG_STRATEGY, strategy}));
  }
}

// PNGs OpenCV cannot write, made here chunk by chunk: palettes, low bit
// depths, Adam7 interlacing, every filter type. OpenCV (libpng) still reads
// them: the reference.
class PngBuilder {
 public:
  PngBuilder(std::uint32_t width, std::uint32_t height, int depth, int colour, bool interlaced)
      : width_(width), height_(height), depth_(depth), colour_(colour), interlaced_(interlaced) {}

  void palette(const std::vector<std::array<std::uint8_t, 3>>& entries) {
    std::vector<std::uint8_t> data;
    for (const auto& e : entries) data.insert(data.end(), e.begin(), e.end());
    plte_ = data;
  }
  // `sample(x, y, channel)` gives each sample; rows are packed MSB first,
  // pass by pass when interlaced.
  template <typename Sample>
  std::vector<std::uint8_t> build(Sample sample, int channels) const {
    static constexpr std::array<std::array<unsigned, 4>, 7> adam7{
        {{0, 0, 8, 8}, {4, 0, 8, 8}, {0, 4, 4, 8}, {2, 0, 4, 4}, {0, 2, 2, 4}, {1, 0, 2, 2}, {0, 1, 1, 2}}};
    std::vector<std::array<unsigned, 4>> passes;
    if (interlaced_) passes.assign(adam7.begin(), adam7.end());
    else passes.push_back({0, 0, 1, 1});
    std::vector<std::uint8_t> raw;
    const std::size_t bpp = std::max(1, channels * depth_ / 8);
    unsigned row_number = 0;
    for (const auto& [x0, y0, dx, dy] : passes) {
      std::vector<std::uint8_t> above;  // the pass's previous row, unfiltered
      for (unsigned y = y0; y < height_; y += dy) {
        if (x0 >= width_) break;
        std::vector<std::uint8_t> row;
        unsigned bits = 0, filled = 0;
        for (unsigned x = x0; x < width_; x += dx) {
          for (int c = 0; c < channels; ++c) {
            const unsigned value = sample(x, y, c);
            if (depth_ == 16) {
              row.push_back(static_cast<std::uint8_t>(value >> 8));
              row.push_back(static_cast<std::uint8_t>(value));
            } else if (depth_ == 8) {
              row.push_back(static_cast<std::uint8_t>(value));
            } else {
              bits = (bits << depth_) | value;
              filled += static_cast<unsigned>(depth_);
              if (filled == 8) {
                row.push_back(static_cast<std::uint8_t>(bits));
                bits = filled = 0;
              }
            }
          }
        }
        if (filled > 0) row.push_back(static_cast<std::uint8_t>(bits << (8 - filled)));
        if (above.empty()) above.assign(row.size(), 0);
        // Rows take the five filter types in turn (OpenCV writes Sub only).
        const int filter = static_cast<int>(row_number++ % 5);
        raw.push_back(static_cast<std::uint8_t>(filter));
        for (std::size_t i = 0; i < row.size(); ++i) {
          const int a = i >= bpp ? row[i - bpp] : 0, b = above[i], c = i >= bpp ? above[i - bpp] : 0;
          int predicted = 0;
          if (filter == 1) predicted = a;
          if (filter == 2) predicted = b;
          if (filter == 3) predicted = (a + b) / 2;
          if (filter == 4) {
            const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
            predicted = pa <= pb && pa <= pc ? a : (pb <= pc ? b : c);
          }
          raw.push_back(static_cast<std::uint8_t>(row[i] - predicted));
        }
        above = row;
      }
    }
    uLongf size = compressBound(static_cast<uLong>(raw.size()));
    std::vector<std::uint8_t> idat(size);
    compress(idat.data(), &size, raw.data(), static_cast<uLong>(raw.size()));
    idat.resize(size);
    std::vector<std::uint8_t> out{137, 80, 78, 71, 13, 10, 26, 10};
    std::vector<std::uint8_t> ihdr;
    append(ihdr, width_);
    append(ihdr, height_);
    ihdr.insert(ihdr.end(), {static_cast<std::uint8_t>(depth_), static_cast<std::uint8_t>(colour_), 0, 0,
                             static_cast<std::uint8_t>(interlaced_ ? 1 : 0)});
    chunk(out, "IHDR", ihdr);
    if (!plte_.empty()) chunk(out, "PLTE", plte_);
    chunk(out, "IDAT", idat);
    chunk(out, "IEND", {});
    return out;
  }

  static void append(std::vector<std::uint8_t>& out, std::uint32_t v) {
    out.insert(out.end(), {static_cast<std::uint8_t>(v >> 24), static_cast<std::uint8_t>(v >> 16),
                           static_cast<std::uint8_t>(v >> 8), static_cast<std::uint8_t>(v)});
  }
  static void chunk(std::vector<std::uint8_t>& out, const char* type, const std::vector<std::uint8_t>& data) {
    append(out, static_cast<std::uint32_t>(data.size()));
    std::vector<std::uint8_t> typed(type, type + 4);
    typed.insert(typed.end(), data.begin(), data.end());
    out.insert(out.end(), typed.begin(), typed.end());
    append(out, static_cast<std::uint32_t>(crc32(0, typed.data(), static_cast<uInt>(typed.size()))));
  }

 private:
  std::uint32_t width_, height_;
  int depth_, colour_;
  bool interlaced_;
  std::vector<std::uint8_t> plte_;
};

TEST(DecodePng, ReadsPalettesLowDepthsAndInterlacingAsOpenCvDoes) {
  const auto pattern = [](unsigned x, unsigned y, int c) { return (x * 5 + y * 11 + static_cast<unsigned>(c) * 29) % 256; };
  for (bool interlaced : {false, true}) {
    SCOPED_TRACE(interlaced ? "interlaced" : "plain");
    for (int depth : {1, 2, 4, 8}) {
      SCOPED_TRACE(depth);
      const unsigned levels = 1u << depth;
      PngBuilder grey(13, 11, depth, 0, interlaced);
      expect_like_opencv(grey.build([&](unsigned x, unsigned y, int) { return (x + 3 * y) % levels; }, 1));
      PngBuilder indexed(13, 11, depth, 3, interlaced);
      std::vector<std::array<std::uint8_t, 3>> entries;
      for (unsigned i = 0; i < levels; ++i) {
        entries.push_back({static_cast<std::uint8_t>(i * 37), static_cast<std::uint8_t>(255 - i * 11),
                           static_cast<std::uint8_t>(i * 91)});
      }
      indexed.palette(entries);
      expect_like_opencv(indexed.build([&](unsigned x, unsigned y, int) { return (2 * x + y) % levels; }, 1), 1);
    }
    expect_like_opencv(PngBuilder(9, 17, 16, 0, interlaced).build([&](unsigned x, unsigned y, int) { return x * 3000 + y * 7; }, 1));
    expect_like_opencv(PngBuilder(9, 17, 8, 4, interlaced).build(pattern, 2));  // grey + alpha
    expect_like_opencv(PngBuilder(9, 17, 8, 6, interlaced).build(pattern, 4), 1);
    // Smaller than an Adam7 block: some passes are empty.
    expect_like_opencv(PngBuilder(3, 2, 8, 0, interlaced).build(pattern, 1));
  }
}

TEST(EncodePng, RoundTripsGreyAndConvertsRgbAsOpenCvReadsIt) {
  const cv::Mat grey = picture(CV_8UC1, 300, 200);
  const std::vector<std::uint8_t> bytes =
      encode_png({grey.data, grey.total()}, grey.cols, grey.rows, 1);
  const Decoded decoded = decode_png(bytes);
  ASSERT_TRUE(decoded.ok()) << decoded.error;
  EXPECT_EQ(0, std::memcmp(decoded.image.pixels.data(), grey.data, grey.total()));
  expect_like_opencv(bytes);

  cv::Mat rgb = picture(CV_8UC3, 40, 30);
  const std::vector<std::uint8_t> colour = encode_png({rgb.data, rgb.total() * 3}, rgb.cols, rgb.rows, 3);
  cv::Mat read = cv::imdecode(cv::Mat(1, static_cast<int>(colour.size()), CV_8UC1, const_cast<std::uint8_t*>(colour.data())),
                              cv::IMREAD_COLOR);
  ASSERT_EQ(read.type(), CV_8UC3);
  cv::Mat bgr;
  cv::Mat channels[3];
  cv::split(rgb, channels);
  std::swap(channels[0], channels[2]);  // OpenCV reads B, G, R; we wrote R, G, B
  cv::merge(channels, 3, bgr);
  EXPECT_EQ(cv::norm(read, bgr, cv::NORM_INF), 0.0);
  expect_like_opencv(colour, 1);

  EXPECT_THROW(encode_png({grey.data, 10}, 300, 200, 1), std::invalid_argument);
  EXPECT_THROW(encode_png({grey.data, grey.total()}, 300, 200, 2), std::invalid_argument);
  EXPECT_THROW(encode_png({}, 0, 0, 1), std::invalid_argument);
}

TEST(DecodePng, DamagedFilesGetAnErrorNeverAnImage) {
  const cv::Mat grey = picture(CV_8UC1);
  const std::vector<std::uint8_t> good = encode_png({grey.data, grey.total()}, grey.cols, grey.rows, 1);
  ASSERT_TRUE(decode_png(good).ok());

  const auto error_of = [](std::vector<std::uint8_t> bytes) { return decode_png(bytes).error; };
  EXPECT_NE(error_of({good.begin(), good.begin() + 40}).find("truncated"), std::string::npos);
  std::vector<std::uint8_t> flipped = good;
  flipped[good.size() / 2] ^= 0x10;  // inside IDAT
  EXPECT_NE(error_of(flipped).find("CRC"), std::string::npos);
  EXPECT_NE(error_of({'P', '5'}).find("not a PNG"), std::string::npos);
  EXPECT_FALSE(is_png(std::vector<std::uint8_t>{137, 80, 78}));

  // A palette image whose pixels point past its two entries.
  PngBuilder indexed(4, 4, 8, 3, false);
  indexed.palette({{0, 0, 0}, {255, 255, 255}});
  EXPECT_NE(decode_png(indexed.build([](unsigned x, unsigned, int) { return x; }, 1)).error.find("palette index"),
            std::string::npos);
  // A header that claims 2^32 - 1 columns.
  PngBuilder huge(0xffffffffu, 1, 8, 0, false);
  std::vector<std::uint8_t> header_only{137, 80, 78, 71, 13, 10, 26, 10};
  std::vector<std::uint8_t> ihdr;
  PngBuilder::append(ihdr, 0x7fffffffu);
  PngBuilder::append(ihdr, 0x7fffffffu);
  ihdr.insert(ihdr.end(), {8, 0, 0, 0, 0});
  PngBuilder::chunk(header_only, "IHDR", ihdr);
  EXPECT_NE(decode_png(header_only).error.find("too large"), std::string::npos);
}

TEST(PngDeclaredSize, ReadsTheHeaderAloneWithoutDecoding) {
  const cv::Mat grey = picture(CV_8UC1, 61, 37);
  std::vector<std::uint8_t> bytes = encode_png({grey.data, grey.total()}, grey.cols, grey.rows, 1);
  bytes.resize(24);  // signature, IHDR's length and type, width and height: nothing more needed
  const auto size = png_declared_size(bytes);
  ASSERT_TRUE(size);
  EXPECT_EQ(size->width, 61);
  EXPECT_EQ(size->height, 37);
  bytes.resize(23);
  EXPECT_FALSE(png_declared_size(bytes));
  EXPECT_FALSE(png_declared_size(std::vector<std::uint8_t>{'P', '5', ' ', '1', ' ', '1'}));
}

}  // namespace png_test
}  // namespace playerkit::image
