// Golden-byte tests of the `blobfinder` interface (wire-format.md §5 "blobfinder", §6:
// drivers send 132 + 22 × blobs bytes).

#include "protocol/messages/blobfinder.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace blobfinder_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(BlobfinderChannel::kWireSize == 4);          // player_blobfinder_header_elt_t
static_assert(BlobfinderBlob::kWireSize == 22);            // player_blobfinder_blob_elt_t
static_assert(BlobfinderData::kWireSize == 7172);          // player_blobfinder_data_t (320 blobs)
static_assert(BlobfinderColorConfig::kWireSize == 13);     // player_blobfinder_color_config_t
static_assert(BlobfinderImagerConfig::kWireSize == 7);     // player_blobfinder_imager_config_t
static_assert(kBlobfinderHeaderSize == 132 && kBlobfinderBlobSize == 22 && kBlobfinderMaxBlobs == 320);

const BlobfinderBlob kBlobA{.color = 0x00A1A2A3,
                            .area = 0xA4A5A6A7,
                            .x = 0xA8A9,
                            .y = 0xAAAB,
                            .left = 0xACAD,
                            .right = 0xAEAF,
                            .top = 0xB0B1,
                            .bottom = 0xB2B3,
                            .range = 0xB4B5};
const BlobfinderBlob kBlobB{.color = 0x00C1C2C3,
                            .area = 0xC4C5C6C7,
                            .x = 0xC8C9,
                            .y = 0xCACB,
                            .left = 0xCCCD,
                            .right = 0xCECF,
                            .top = 0xD0D1,
                            .bottom = 0xD2D3,
                            .range = 0xD4D5};
const BlobfinderBlob kBlobC{.color = 0x00E1E2E3,
                            .area = 0x01020304,
                            .x = 0x0506,
                            .y = 0x0708,
                            .left = 0x090A,
                            .right = 0x0B0C,
                            .top = 0x0D0E,
                            .bottom = 0x0F10,
                            .range = 0x1112};

// One blob entry is 22 bytes: color @+0 uint32, area @+4 uint32, x @+8, y @+10,
// left @+12, right @+14, top @+16, bottom @+18, range @+20 (uint16 each).
void put_blob_a(WireBytes& w, std::size_t at) {
  w.at(at + 0, {0x00, 0xA1, 0xA2, 0xA3})  // color
      .at(at + 4, {0xA4, 0xA5, 0xA6, 0xA7})  // area
      .at(at + 8, {0xA8, 0xA9})              // x
      .at(at + 10, {0xAA, 0xAB})             // y
      .at(at + 12, {0xAC, 0xAD})             // left
      .at(at + 14, {0xAE, 0xAF})             // right
      .at(at + 16, {0xB0, 0xB1})             // top
      .at(at + 18, {0xB2, 0xB3})             // bottom
      .at(at + 20, {0xB4, 0xB5});            // range
}
void put_blob_b(WireBytes& w, std::size_t at) {
  w.at(at + 0, {0x00, 0xC1, 0xC2, 0xC3})  // color
      .at(at + 4, {0xC4, 0xC5, 0xC6, 0xC7})  // area
      .at(at + 8, {0xC8, 0xC9})              // x
      .at(at + 10, {0xCA, 0xCB})             // y
      .at(at + 12, {0xCC, 0xCD})             // left
      .at(at + 14, {0xCE, 0xCF})             // right
      .at(at + 16, {0xD0, 0xD1})             // top
      .at(at + 18, {0xD2, 0xD3})             // bottom
      .at(at + 20, {0xD4, 0xD5});            // range
}
void put_blob_c(WireBytes& w, std::size_t at) {
  w.at(at + 0, {0x00, 0xE1, 0xE2, 0xE3})  // color
      .at(at + 4, {0x01, 0x02, 0x03, 0x04})  // area
      .at(at + 8, {0x05, 0x06})              // x
      .at(at + 10, {0x07, 0x08})             // y
      .at(at + 12, {0x09, 0x0A})             // left
      .at(at + 14, {0x0B, 0x0C})             // right
      .at(at + 16, {0x0D, 0x0E})             // top
      .at(at + 18, {0x0F, 0x10})             // bottom
      .at(at + 20, {0x11, 0x12});            // range
}

TEST(BlobfinderGolden, BlobEntry) {
  WireBytes w(22);
  put_blob_a(w, 0);
  EXPECT_TRUE(MatchesGolden(kBlobA, w.done()));
  EXPECT_TRUE(golden::HasFields(to_json(kBlobA),
                                {"color", "area", "x", "y", "left", "right", "top", "bottom", "range"}));
  EXPECT_TRUE(Rejects<BlobfinderBlob>(golden::drop_last(w.done()), "range", 22, 21));
}

TEST(BlobfinderGolden, ChannelHeaderEntry) {
  const BlobfinderChannel value{.index = 0x0102, .num = 0x0304};
  EXPECT_TRUE(MatchesGolden(value, Bytes{0x01, 0x02,     // index @0 uint16
                                         0x03, 0x04}));  // num   @2 uint16
  EXPECT_TRUE(golden::HasFields(to_json(value), {"index", "num"}));
}

// The 132-byte block every data packet starts with: width, height, 32 channel entries.
BlobfinderData header_block() {
  BlobfinderData d{.width = 0x0102, .height = 0x0304};
  d.header[31] = {.index = 0x1F01, .num = 0x1F02};
  return d;
}
TEST(BlobfinderGolden, DataWithNoBlobsIs132Bytes) {
  const BlobfinderData value = header_block();
  const Bytes golden_bytes = WireBytes(132)
                                 .at(0, {0x01, 0x02})                // width      @0   uint16
                                 .at(2, {0x03, 0x04})                // height     @2   uint16
                                 .zeros(4, 31 * 4)                   // header[0..30] @4..127
                                 .at(128, {0x1F, 0x01, 0x1F, 0x02})  // header[31] @128 index, num
                                 .done();
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  EXPECT_TRUE(SurvivesJson(value));
}

BlobfinderData one_blob() {
  BlobfinderData d = header_block();
  d.header[0] = {.index = 0, .num = 1};
  d.blobs = {kBlobA};
  return d;
}

Bytes one_blob_bytes() {
  WireBytes w(132 + 22 * 1);
  w.at(0, {0x01, 0x02})                // width      @0   uint16
      .at(2, {0x03, 0x04})             // height     @2   uint16
      .at(4, {0x00, 0x00, 0x00, 0x01})  // header[0]  @4   index 0, num 1
      .zeros(8, 30 * 4)                // header[1..30] @8..127
      .at(128, {0x1F, 0x01, 0x1F, 0x02});  // header[31] @128
  put_blob_a(w, 132);                  // blobs[0]   @132
  return w.done();
}

TEST(BlobfinderGolden, DataWithOneBlobIs154Bytes) {
  EXPECT_TRUE(EncodesTo(one_blob(), one_blob_bytes()));
  EXPECT_TRUE(DecodesTo(one_blob_bytes(), one_blob()));
  const auto j = to_json(one_blob());
  EXPECT_TRUE(golden::HasFields(j, {"width", "height", "header", "blobs"}));
  EXPECT_EQ(j.at("width"), 0x0102);
  EXPECT_EQ(j.at("header").size(), 32u);
  EXPECT_EQ(j.at("header")[31], (nlohmann::json{{"index", 0x1F01}, {"num", 0x1F02}}));
  ASSERT_EQ(j.at("blobs").size(), 1u);
  EXPECT_EQ(j.at("blobs")[0].at("color"), 0x00A1A2A3);
  EXPECT_EQ(j.at("blobs")[0].at("range"), 0xB4B5);
  EXPECT_TRUE(SurvivesJson(one_blob()));
}

BlobfinderData three_blobs() {
  BlobfinderData d = header_block();
  d.header[0] = {.index = 0, .num = 2};
  d.header[2] = {.index = 2, .num = 1};
  d.blobs = {kBlobA, kBlobB, kBlobC};
  return d;
}

Bytes three_blobs_bytes() {
  WireBytes w(132 + 22 * 3);
  w.at(0, {0x01, 0x02})                    // width      @0   uint16
      .at(2, {0x03, 0x04})                 // height     @2   uint16
      .at(4, {0x00, 0x00, 0x00, 0x02})     // header[0]  @4   index 0, num 2
      .zeros(8, 4)                         // header[1]  @8
      .at(12, {0x00, 0x02, 0x00, 0x01})    // header[2]  @12  index 2, num 1
      .zeros(16, 28 * 4)                   // header[3..30] @16..127
      .at(128, {0x1F, 0x01, 0x1F, 0x02});  // header[31] @128
  put_blob_a(w, 132);                      // blobs[0]   @132
  put_blob_b(w, 154);                      // blobs[1]   @154
  put_blob_c(w, 176);                      // blobs[2]   @176..197
  return w.done();
}

TEST(BlobfinderGolden, DataWithThreeBlobsIs198Bytes) {
  EXPECT_EQ(three_blobs_bytes().size(), 198u);
  EXPECT_TRUE(EncodesTo(three_blobs(), three_blobs_bytes()));
  EXPECT_TRUE(DecodesTo(three_blobs_bytes(), three_blobs()));
  EXPECT_EQ(to_json(three_blobs()).at("blobs").size(), 3u);
  EXPECT_TRUE(SurvivesJson(three_blobs()));
}

TEST(BlobfinderGolden, RaggedBlobListIsRejected) {
  const Bytes three = three_blobs_bytes();
  // 197 bytes: 65 bytes of blobs are not a whole number of 22-byte entries.
  EXPECT_TRUE(Rejects<BlobfinderData>(golden::drop_last(three), "blobs", 22, 65));
  EXPECT_TRUE(Rejects<BlobfinderData>(Bytes(three.begin(), three.begin() + 132 + 21), "blobs", 22, 21));
  EXPECT_TRUE(Rejects<BlobfinderData>(Bytes(three.begin(), three.begin() + 132 + 23), "blobs", 22, 23));
  EXPECT_TRUE(Rejects<BlobfinderData>(golden::with_extra_byte(three), "blobs", 22, 67));
}

TEST(BlobfinderGolden, IncompleteHeaderBlockIsRejected) {
  const Bytes three = three_blobs_bytes();
  EXPECT_TRUE(Rejects<BlobfinderData>(Bytes(three.begin(), three.begin() + 131), "header", 132, 131));
  EXPECT_TRUE(Rejects<BlobfinderData>(Bytes(three.begin(), three.begin() + 3), "height", 132, 3));
  EXPECT_TRUE(Rejects<BlobfinderData>(golden::kEmpty, "width", 132, 0));
}

TEST(BlobfinderGolden, AtMost320Blobs) {
  BlobfinderData full = header_block();
  full.blobs.assign(320, kBlobC);
  const Bytes bytes = encode(full);
  ASSERT_EQ(bytes.size(), 7172u);
  // The last blob ends the payload: its range (0x1112) is in the last two bytes.
  EXPECT_EQ(bytes[7170], 0x11);
  EXPECT_EQ(bytes[7171], 0x12);
  EXPECT_TRUE(DecodesTo(bytes, full));

  Bytes too_many = bytes;
  too_many.insert(too_many.end(), bytes.end() - 22, bytes.end());  // 321 blobs
  EXPECT_TRUE(Rejects<BlobfinderData>(too_many, "", 7172, 7194));

  full.blobs.push_back(kBlobC);
  EXPECT_THROW((void)encode(full), EncodeError);
}

TEST(BlobfinderGolden, ColorConfig) {
  const BlobfinderColorConfig value{.subtype = kBlobfinderSetColorReq,
                                    .rmin = ~0x0102,
                                    .rmax = 0x0304,
                                    .gmin = ~0x0506,
                                    .gmax = 0x0708,
                                    .bmin = ~0x090A,
                                    .bmax = 0x0B0C};
  const Bytes golden_bytes{0x01,        // subtype @0  uint8 = PLAYER_BLOBFINDER_SET_COLOR_REQ (1)
                           0xFE, 0xFD,  // rmin    @1  int16 = ~0x0102
                           0x03, 0x04,  // rmax    @3  int16
                           0xFA, 0xF9,  // gmin    @5  int16 = ~0x0506
                           0x07, 0x08,  // gmax    @7  int16
                           0xF6, 0xF5,  // bmin    @9  int16 = ~0x090A
                           0x0B, 0x0C};  // bmax   @11 int16
  ASSERT_EQ(golden_bytes.size(), 13u);
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "rmin", "rmax", "gmin", "gmax", "bmin", "bmax"}));
  EXPECT_EQ(j.at("rmin"), -0x0103);
  EXPECT_TRUE(Rejects<BlobfinderColorConfig>(golden::drop_last(golden_bytes), "bmax", 13, 12));
  EXPECT_TRUE(Rejects<BlobfinderColorConfig>(golden::with_extra_byte(golden_bytes), "", 13, 14));
}

TEST(BlobfinderGolden, ImagerConfig) {
  const BlobfinderImagerConfig value{.subtype = kBlobfinderSetImagerParamsReq,
                                     .brightness = ~0x0102,
                                     .contrast = 0x0304,
                                     .colormode = ~0x05,
                                     .autogain = -1};
  const Bytes golden_bytes{0x02,        // subtype    @0 uint8 = PLAYER_BLOBFINDER_SET_IMAGER_PARAMS_REQ (2)
                           0xFE, 0xFD,  // brightness @1 int16 = ~0x0102
                           0x03, 0x04,  // contrast   @3 int16
                           0xFA,        // colormode  @5 int8 = ~0x05 = -6
                           0xFF};       // autogain   @6 int8 = -1 (unchanged)
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "brightness", "contrast", "colormode", "autogain"}));
  EXPECT_EQ(j.at("colormode"), -6);
  EXPECT_EQ(j.at("autogain"), -1);
  EXPECT_TRUE(Rejects<BlobfinderImagerConfig>(golden::drop_last(golden_bytes), "autogain", 7, 6));
  EXPECT_TRUE(Rejects<BlobfinderImagerConfig>(golden::with_extra_byte(golden_bytes), "", 7, 8));
}

}  // namespace blobfinder_test
}  // namespace playerkit::protocol
