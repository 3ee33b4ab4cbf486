// Golden-byte tests of the `localize` interface (wire-format.md §5 "localize", §1: int64
// is big-endian, most significant byte first; §6: amcl sends 14 + 88 × hypoth_count bytes).

#include "protocol/messages/localize.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace localize_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(LocalizeHypothesis::kWireSize == 88);    // player_localize_hypoth_t
static_assert(LocalizeData::kWireSize == 894);         // player_localize_data_t: 14 + 10 × 88
static_assert(LocalizeSetPose::kWireSize == 85);       // player_localize_set_pose_t
static_assert(LocalizeConfig::kWireSize == 5);         // player_localize_config_t
static_assert(LocalizeMapInfo::kWireSize == 13);       // player_localize_map_info_t
static_assert(LocalizeMapData::kWireSize == 4096);     // player_localize_map_data_t

const LocalizeHypothesis kHypothA{
    .mean = {0x01020304, ~0x05060708, 0x090A0B0C},
    .cov = {{{0x0102030405060708, ~0x1112131415161718, 0x2122232425262728},
             {0x3132333435363738, ~0x4142434445464748, 0x5152535455565758},
             {0x6162636465666768, 0x7172737475767778, ~0x0A0B0C0D0E0F1011}}},
    .alpha = 0x8A8B8C8D};

const LocalizeHypothesis kHypothB{.mean = {~0x1A1B1C1D, 0x2A2B2C2D, ~0x3A3B3C3D},
                                  .cov = {{{0x0011223344556677, 0, 0},
                                           {0, 0x0123456789ABCDEF, 0},
                                           {0, 0, 0x7FEEDDCCBBAA9988}}},
                                  .alpha = 0x9A9B9C9D};

// player_localize_hypoth_t at `at` (88 bytes): mean @+0 int32[3], cov @+12 int64[3][3]
// row-major (8 bytes each, most significant first), alpha @+84 uint32.
void put_hypoth_a(WireBytes& w, std::size_t at) {
  w.at(at + 0, {0x01, 0x02, 0x03, 0x04})                          // mean[0]
      .at(at + 4, {0xFA, 0xF9, 0xF8, 0xF7})                       // mean[1] = ~0x05060708
      .at(at + 8, {0x09, 0x0A, 0x0B, 0x0C})                       // mean[2]
      .at(at + 12, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08})  // cov[0][0]
      .at(at + 20, {0xEE, 0xED, 0xEC, 0xEB, 0xEA, 0xE9, 0xE8, 0xE7})  // cov[0][1] = ~0x1112131415161718
      .at(at + 28, {0x21, 0x22, 0x23, 0x24, 0x25, 0x26, 0x27, 0x28})  // cov[0][2]
      .at(at + 36, {0x31, 0x32, 0x33, 0x34, 0x35, 0x36, 0x37, 0x38})  // cov[1][0]
      .at(at + 44, {0xBE, 0xBD, 0xBC, 0xBB, 0xBA, 0xB9, 0xB8, 0xB7})  // cov[1][1] = ~0x4142434445464748
      .at(at + 52, {0x51, 0x52, 0x53, 0x54, 0x55, 0x56, 0x57, 0x58})  // cov[1][2]
      .at(at + 60, {0x61, 0x62, 0x63, 0x64, 0x65, 0x66, 0x67, 0x68})  // cov[2][0]
      .at(at + 68, {0x71, 0x72, 0x73, 0x74, 0x75, 0x76, 0x77, 0x78})  // cov[2][1]
      .at(at + 76, {0xF5, 0xF4, 0xF3, 0xF2, 0xF1, 0xF0, 0xEF, 0xEE})  // cov[2][2] = ~0x0A0B0C0D0E0F1011
      .at(at + 84, {0x8A, 0x8B, 0x8C, 0x8D});                         // alpha
}

void put_hypoth_b(WireBytes& w, std::size_t at) {
  w.at(at + 0, {0xE5, 0xE4, 0xE3, 0xE2})                          // mean[0] = ~0x1A1B1C1D
      .at(at + 4, {0x2A, 0x2B, 0x2C, 0x2D})                       // mean[1]
      .at(at + 8, {0xC5, 0xC4, 0xC3, 0xC2})                       // mean[2] = ~0x3A3B3C3D
      .at(at + 12, {0x00, 0x11, 0x22, 0x33, 0x44, 0x55, 0x66, 0x77})  // cov[0][0]
      .zeros(at + 20, 3 * 8)                                          // cov[0][1], cov[0][2], cov[1][0]
      .at(at + 44, {0x01, 0x23, 0x45, 0x67, 0x89, 0xAB, 0xCD, 0xEF})  // cov[1][1]
      .zeros(at + 52, 3 * 8)                                          // cov[1][2], cov[2][0], cov[2][1]
      .at(at + 76, {0x7F, 0xEE, 0xDD, 0xCC, 0xBB, 0xAA, 0x99, 0x88})  // cov[2][2]
      .at(at + 84, {0x9A, 0x9B, 0x9C, 0x9D});                         // alpha
}

TEST(LocalizeGolden, HypothesisWithInt64Covariance) {
  WireBytes w(88);
  put_hypoth_a(w, 0);
  const Bytes golden_bytes = w.done();
  EXPECT_TRUE(MatchesGolden(kHypothA, golden_bytes));
  const LocalizeHypothesis decoded = decode<LocalizeHypothesis>(golden_bytes);
  EXPECT_EQ(decoded.cov[0][0], 0x0102030405060708);
  EXPECT_EQ(decoded.cov[0][1], -0x1112131415161719);
  const auto j = to_json(kHypothA);
  EXPECT_TRUE(golden::HasFields(j, {"mean", "cov", "alpha"}));
  EXPECT_EQ(j.at("cov")[0][0], 0x0102030405060708);
  EXPECT_EQ(j.at("cov")[0][1], -0x1112131415161719);
  EXPECT_EQ(j.at("cov")[2][2], -0x0A0B0C0D0E0F1012);
  EXPECT_EQ(j.at("alpha"), 0x8A8B8C8Du);
}

LocalizeData with_hypotheses(std::uint32_t count) {
  LocalizeData d{.pending_count = 0x0102, .pending_time_sec = 0x03040506, .pending_time_usec = 0x0708090A,
                 .hypoth_count = count};
  if (count >= 1) d.hypoths[0] = kHypothA;
  if (count >= 2) d.hypoths[1] = kHypothB;
  return d;
}

// The 14-byte block before the hypotheses.
void put_localize_header(WireBytes& w, std::uint8_t count) {
  w.at(0, {0x01, 0x02})                  // pending_count     @0  uint16
      .at(2, {0x03, 0x04, 0x05, 0x06})   // pending_time_sec  @2  uint32
      .at(6, {0x07, 0x08, 0x09, 0x0A})   // pending_time_usec @6  uint32
      .at(10, {0x00, 0x00, 0x00, count});  // hypoth_count    @10 uint32
}

Bytes no_hypotheses_bytes() {
  WireBytes w(14);
  put_localize_header(w, 0);
  return w.done();
}

Bytes one_hypothesis_bytes() {
  WireBytes w(14 + 88);
  put_localize_header(w, 1);
  put_hypoth_a(w, 14);  // hypoths[0] @14
  return w.done();
}

Bytes two_hypotheses_bytes() {
  WireBytes w(14 + 2 * 88);
  put_localize_header(w, 2);
  put_hypoth_a(w, 14);   // hypoths[0] @14
  put_hypoth_b(w, 102);  // hypoths[1] @102..189
  return w.done();
}

TEST(LocalizeGolden, DataWithNoHypothesesIs14Bytes) {
  EXPECT_TRUE(EncodesTo(with_hypotheses(0), no_hypotheses_bytes()));
  EXPECT_TRUE(DecodesTo(no_hypotheses_bytes(), with_hypotheses(0)));
  EXPECT_TRUE(SurvivesJson(with_hypotheses(0)));
}

TEST(LocalizeGolden, DataWithOneHypothesisIs102Bytes) {
  EXPECT_TRUE(EncodesTo(with_hypotheses(1), one_hypothesis_bytes()));
  EXPECT_TRUE(DecodesTo(one_hypothesis_bytes(), with_hypotheses(1)));
  EXPECT_TRUE(SurvivesJson(with_hypotheses(1)));
}

TEST(LocalizeGolden, DataWithTwoHypothesesIs190Bytes) {
  EXPECT_TRUE(EncodesTo(with_hypotheses(2), two_hypotheses_bytes()));
  EXPECT_TRUE(DecodesTo(two_hypotheses_bytes(), with_hypotheses(2)));
  const auto j = to_json(with_hypotheses(2));
  EXPECT_TRUE(golden::HasFields(j, {"pending_count", "pending_time_sec", "pending_time_usec", "hypoth_count",
                                    "hypoths"}));
  EXPECT_EQ(j.at("hypoth_count"), 2);
  ASSERT_EQ(j.at("hypoths").size(), 2u);
  EXPECT_EQ(j.at("hypoths")[1].at("cov")[2][2], 0x7FEEDDCCBBAA9988);
  EXPECT_EQ(j.at("hypoths")[1].at("mean")[0], -0x1A1B1C1E);
  EXPECT_TRUE(SurvivesJson(with_hypotheses(2)));
}

TEST(LocalizeGolden, FullSizeFormIsAlsoAccepted) {
  // The whole 894-byte struct, unused hypotheses zero: decodes to the same value, and
  // re-encodes in the short form amcl sends.
  WireBytes w(894);
  put_localize_header(w, 2);
  put_hypoth_a(w, 14);
  put_hypoth_b(w, 102);
  w.zeros(190, 8 * 88);  // hypoths[2..9] @190..893
  const Bytes full = w.done();
  EXPECT_TRUE(DecodesTo(full, with_hypotheses(2)));
  EXPECT_TRUE(EncodesTo(with_hypotheses(2), two_hypotheses_bytes()));
  EXPECT_TRUE(Rejects<LocalizeData>(golden::with_extra_byte(full), "", 894, 895));
}

TEST(LocalizeGolden, HypothCountLargerThanTheHypothesesPresentIsRejected) {
  Bytes bytes = two_hypotheses_bytes();
  bytes[13] = 3;  // hypoth_count @10 = 3, but only 2 hypotheses follow
  EXPECT_TRUE(Rejects<LocalizeData>(bytes, "hypoths", 14 + 3 * 88, 190));
  Bytes header_only = no_hypotheses_bytes();
  header_only[13] = 1;
  EXPECT_TRUE(Rejects<LocalizeData>(header_only, "hypoths", 102, 14));
}

TEST(LocalizeGolden, HypothCountAbove10IsRejected) {
  Bytes bytes = no_hypotheses_bytes();
  bytes[13] = 11;  // hypoth_count @10 = 11 > PLAYER_LOCALIZE_MAX_HYPOTHS
  EXPECT_TRUE(Rejects<LocalizeData>(bytes, "hypoths", 10, 11));
  bytes[13] = 0;
  bytes[12] = 1;  // hypoth_count = 0x00000100 = 256: the count is a full uint32
  EXPECT_TRUE(Rejects<LocalizeData>(bytes, "hypoths", 10, 256));
}

TEST(LocalizeGolden, TruncatedOrRaggedDataIsRejected) {
  const Bytes two = two_hypotheses_bytes();
  EXPECT_TRUE(Rejects<LocalizeData>(golden::drop_last(two), "hypoths", 190, 189));
  EXPECT_TRUE(Rejects<LocalizeData>(golden::kEmpty, "pending_count", 14, 0));
  EXPECT_TRUE(Rejects<LocalizeData>(Bytes(two.begin(), two.begin() + 13), "hypoth_count", 14, 13));
  // Two whole hypotheses plus 5 stray bytes: 181 bytes after the header.
  Bytes ragged = two;
  ragged.insert(ragged.end(), {0x01, 0x02, 0x03, 0x04, 0x05});
  EXPECT_TRUE(Rejects<LocalizeData>(ragged, "hypoths", 88, 181));
}

TEST(LocalizeGolden, EncodeRejectsHypothCountAbove10) {
  LocalizeData bad = with_hypotheses(2);
  bad.hypoth_count = 11;
  EXPECT_THROW((void)encode(bad), EncodeError);
}

TEST(LocalizeGolden, SetPoseRequest) {
  const LocalizeSetPose value{.subtype = kLocalizeSetPoseReq, .mean = kHypothA.mean, .cov = kHypothA.cov};
  const Bytes golden_bytes = WireBytes(85)
                                 .at(0, {0x01})  // subtype @0 uint8 = PLAYER_LOCALIZE_SET_POSE_REQ (1)
                                 // mean @1 int32[3]
                                 .at(1, {0x01, 0x02, 0x03, 0x04})
                                 .at(5, {0xFA, 0xF9, 0xF8, 0xF7})
                                 .at(9, {0x09, 0x0A, 0x0B, 0x0C})
                                 // cov @13 int64[3][3], row-major
                                 .at(13, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06, 0x07, 0x08})  // cov[0][0]
                                 .at(21, {0xEE, 0xED, 0xEC, 0xEB, 0xEA, 0xE9, 0xE8, 0xE7})  // cov[0][1]
                                 .at(29, {0x21, 0x22, 0x23, 0x24, 0x25, 0x26, 0x27, 0x28})  // cov[0][2]
                                 .at(37, {0x31, 0x32, 0x33, 0x34, 0x35, 0x36, 0x37, 0x38})  // cov[1][0]
                                 .at(45, {0xBE, 0xBD, 0xBC, 0xBB, 0xBA, 0xB9, 0xB8, 0xB7})  // cov[1][1]
                                 .at(53, {0x51, 0x52, 0x53, 0x54, 0x55, 0x56, 0x57, 0x58})  // cov[1][2]
                                 .at(61, {0x61, 0x62, 0x63, 0x64, 0x65, 0x66, 0x67, 0x68})  // cov[2][0]
                                 .at(69, {0x71, 0x72, 0x73, 0x74, 0x75, 0x76, 0x77, 0x78})  // cov[2][1]
                                 .at(77, {0xF5, 0xF4, 0xF3, 0xF2, 0xF1, 0xF0, 0xEF, 0xEE})  // cov[2][2]
                                 .done();
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "mean", "cov"}));
  EXPECT_TRUE(Rejects<LocalizeSetPose>(golden::drop_last(golden_bytes), "cov", 85, 84));
  EXPECT_TRUE(Rejects<LocalizeSetPose>(golden::with_extra_byte(golden_bytes), "", 85, 86));
}

TEST(LocalizeGolden, ConfigRequest) {
  const LocalizeConfig value{.subtype = kLocalizeSetConfigReq, .num_particles = 0x01020304};
  const Bytes golden_bytes{0x03,                     // subtype       @0 uint8 = PLAYER_LOCALIZE_SET_CONFIG_REQ (3)
                           0x01, 0x02, 0x03, 0x04};  // num_particles @1 uint32
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "num_particles"}));
  EXPECT_TRUE(Rejects<LocalizeConfig>(golden::drop_last(golden_bytes), "num_particles", 5, 4));
}

TEST(LocalizeGolden, MapInfoRequest) {
  const LocalizeMapInfo value{
      .subtype = kLocalizeGetMapInfoReq, .scale = 0x01020304, .width = 0x05060708, .height = 0x090A0B0C};
  const Bytes golden_bytes{0x04,                     // subtype @0 uint8 = PLAYER_LOCALIZE_GET_MAP_INFO_REQ (4)
                           0x01, 0x02, 0x03, 0x04,   // scale   @1 uint32
                           0x05, 0x06, 0x07, 0x08,   // width   @5 uint32
                           0x09, 0x0A, 0x0B, 0x0C};  // height  @9 uint32
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "scale", "width", "height"}));
  EXPECT_TRUE(Rejects<LocalizeMapInfo>(golden::drop_last(golden_bytes), "height", 13, 12));
  EXPECT_TRUE(Rejects<LocalizeMapInfo>(golden::with_extra_byte(golden_bytes), "", 13, 14));
}

TEST(LocalizeGolden, MapDataRequestIsTheTileHeader) {
  const LocalizeMapData request{
      .subtype = kLocalizeGetMapDataReq, .col = 0x01020304, .row = 0x05060708, .width = 3, .height = 2, .data = {}};
  const Bytes golden_bytes{0x05,                     // subtype @0  uint8 = PLAYER_LOCALIZE_GET_MAP_DATA_REQ (5)
                           0x01, 0x02, 0x03, 0x04,   // col     @1  uint32
                           0x05, 0x06, 0x07, 0x08,   // row     @5  uint32
                           0x00, 0x00, 0x00, 0x03,   // width   @9  uint32
                           0x00, 0x00, 0x00, 0x02};  // height  @13 uint32
  EXPECT_TRUE(MatchesGolden(request, golden_bytes));
  EXPECT_TRUE(Rejects<LocalizeMapData>(golden::drop_last(golden_bytes), "height", 17, 16));
  EXPECT_TRUE(Rejects<LocalizeMapData>(golden::kEmpty, "subtype", 17, 0));
}

TEST(LocalizeGolden, MapDataReplyCarriesTheCells) {
  const LocalizeMapData reply{.subtype = kLocalizeGetMapDataReq,
                              .col = 0x01020304,
                              .row = 0x05060708,
                              .width = 3,
                              .height = 2,
                              .data = {-1, 0, 1, 1, -1, 0}};
  const Bytes golden_bytes{0x05,                    // subtype @0
                           0x01, 0x02, 0x03, 0x04,  // col     @1
                           0x05, 0x06, 0x07, 0x08,  // row     @5
                           0x00, 0x00, 0x00, 0x03,  // width   @9
                           0x00, 0x00, 0x00, 0x02,  // height  @13
                           0xFF, 0x00, 0x01,        // data    @17 int8: -1 empty, 0 unknown, +1 occupied
                           0x01, 0xFF, 0x00};
  EXPECT_TRUE(MatchesGolden(reply, golden_bytes));
  const auto j = to_json(reply);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "col", "row", "width", "height", "data"}));
  EXPECT_EQ(j.at("data"), (nlohmann::json{-1, 0, 1, 1, -1, 0}));

  // The largest reply is exactly PLAYER_MAX_REQREP_SIZE: 17 + 4079 cells.
  Bytes largest = golden_bytes;
  largest.resize(4096, 0x01);
  EXPECT_TRUE(golden::Accepts<LocalizeMapData>(largest));
  EXPECT_EQ(decode<LocalizeMapData>(largest).data.size(), 4079u);
  EXPECT_TRUE(Rejects<LocalizeMapData>(golden::with_extra_byte(largest), "", 4096, 4097));
}

}  // namespace localize_test
}  // namespace playerkit::protocol
