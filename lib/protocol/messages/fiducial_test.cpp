// Golden-byte tests of the `fiducial` interface (wire-format.md §5 "fiducial", §7:
// the geometry pose is declared uint16 but read as int16 by playerkit).

#include "protocol/messages/fiducial.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace fiducial_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(FiducialItem::kWireSize == 14);             // player_fiducial_item_t
static_assert(FiducialData::kWireSize == 450);            // player_fiducial_data_t
static_assert(FiducialGeom::kWireSize == 15);             // player_fiducial_geom_t
static_assert(FiducialFov::kWireSize == 7);               // player_fiducial_fov_t
static_assert(FiducialMsg::kWireSize == 38);              // player_fiducial_msg_t
static_assert(FiducialMsgRxRequest::kWireSize == 2);      // player_fiducial_msg_rx_req_t
static_assert(FiducialMsgTxRequest::kWireSize == 40);     // player_fiducial_msg_tx_req_t
static_assert(FiducialMsgTxRxRequest::kWireSize == 41);   // player_fiducial_msg_txrx_req_t

TEST(FiducialGolden, Item) {
  const FiducialItem value{.id = 0x0102, .pose = {0x0304, ~0x0506, 0x0708}, .upose = {0x090A, 0x0B0C, 0x0D0E}};
  const Bytes golden_bytes{0x01, 0x02,                          // id    @0 int16
                           0x03, 0x04, 0xFA, 0xF9, 0x07, 0x08,  // pose  @2 int16[3], bearing = ~0x0506
                           0x09, 0x0A, 0x0B, 0x0C, 0x0D, 0x0E};  // upose @8 int16[3]
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"id", "pose", "upose"}));
}

FiducialData two_fiducials() {
  FiducialData d{.count = 2};
  d.fiducials[0] = {.id = 0x0102, .pose = {0x0304, ~0x0506, 0x0708}, .upose = {0x090A, 0x0B0C, 0x0D0E}};
  d.fiducials[1] = {.id = -1, .pose = {0x1112, 0x1314, ~0x1516}, .upose = {0x1718, 0x191A, 0x1B1C}};
  return d;
}

Bytes two_fiducials_bytes() {
  return WireBytes(450)
      .at(0, {0x00, 0x02})  // count @0 uint16 = 2
      // fiducials[0] @2: id @2, pose @4, upose @10
      .at(2, {0x01, 0x02})
      .at(4, {0x03, 0x04, 0xFA, 0xF9, 0x07, 0x08})
      .at(10, {0x09, 0x0A, 0x0B, 0x0C, 0x0D, 0x0E})
      // fiducials[1] @16: id @16 = -1 (unidentified), pose @18, upose @24
      .at(16, {0xFF, 0xFF})
      .at(18, {0x11, 0x12, 0x13, 0x14, 0xEA, 0xE9})
      .at(24, {0x17, 0x18, 0x19, 0x1A, 0x1B, 0x1C})
      .zeros(30, 30 * 14)  // fiducials[2..31] @30..449
      .done();
}

TEST(FiducialGolden, DataPacket) {
  EXPECT_TRUE(EncodesTo(two_fiducials(), two_fiducials_bytes()));
  EXPECT_TRUE(DecodesTo(two_fiducials_bytes(), two_fiducials()));
  const auto j = to_json(two_fiducials());
  EXPECT_TRUE(golden::HasFields(j, {"count", "fiducials"}));
  ASSERT_EQ(j.at("fiducials").size(), 2u);
  EXPECT_EQ(j.at("fiducials")[1].at("id"), -1);
  EXPECT_EQ(j.at("fiducials")[1].at("pose"), (nlohmann::json{0x1112, 0x1314, -0x1517}));
  EXPECT_TRUE(SurvivesJson(two_fiducials()));
}

TEST(FiducialGolden, DataCountAndLengthAreChecked) {
  Bytes bytes = two_fiducials_bytes();
  bytes[1] = 33;  // count @0 = 33 > PLAYER_FIDUCIAL_MAX_SAMPLES
  EXPECT_TRUE(Rejects<FiducialData>(bytes, "fiducials", 32, 33));
  EXPECT_TRUE(Rejects<FiducialData>(golden::drop_last(two_fiducials_bytes()), "fiducials", 450, 449));
  EXPECT_TRUE(Rejects<FiducialData>(golden::kEmpty, "count", 450, 0));
  EXPECT_TRUE(Rejects<FiducialData>(golden::with_extra_byte(two_fiducials_bytes()), "", 450, 451));
}

TEST(FiducialGolden, GeometryPoseIsSigned) {
  const FiducialGeom value{.subtype = kFiducialGetGeom,
                           .pose = {~0x0102, 0x0304, ~0x0506},
                           .size = {0x0708, 0x090A},
                           .fiducial_size = {0x0B0C, 0x0D0E}};
  const Bytes golden_bytes{0x01,                    // subtype       @0  uint8 = PLAYER_FIDUCIAL_GET_GEOM (1)
                           0xFE, 0xFD,              // pose[0]       @1  x = ~0x0102 (declared uint16)
                           0x03, 0x04,              // pose[1]       @3  y
                           0xFA, 0xF9,              // pose[2]       @5  yaw = ~0x0506
                           0x07, 0x08, 0x09, 0x0A,  // size          @7  uint16[2]
                           0x0B, 0x0C, 0x0D, 0x0E};  // fiducial_size @11 uint16[2]
  ASSERT_EQ(golden_bytes.size(), 15u);
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_EQ(decode<FiducialGeom>(golden_bytes).pose[0], -0x0103);
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "pose", "size", "fiducial_size"}));
  EXPECT_EQ(j.at("pose"), (nlohmann::json{-0x0103, 0x0304, -0x0507}));
  EXPECT_TRUE(Rejects<FiducialGeom>(golden::drop_last(golden_bytes), "fiducial_size", 15, 14));
  EXPECT_TRUE(Rejects<FiducialGeom>(golden::with_extra_byte(golden_bytes), "", 15, 16));
}

TEST(FiducialGolden, FieldOfView) {
  const FiducialFov value{.subtype = kFiducialSetFov, .min_range = 0x0102, .max_range = 0x0304, .view_angle = 0x0506};
  const Bytes golden_bytes{0x03,         // subtype    @0 uint8 = PLAYER_FIDUCIAL_SET_FOV (3)
                           0x01, 0x02,   // min_range  @1 uint16
                           0x03, 0x04,   // max_range  @3 uint16
                           0x05, 0x06};  // view_angle @5 uint16
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "min_range", "max_range", "view_angle"}));
  EXPECT_TRUE(Rejects<FiducialFov>(golden::drop_last(golden_bytes), "view_angle", 7, 6));
}

FiducialMsg four_byte_msg() {
  FiducialMsg m{.target_id = ~0x01020304, .len = 4, .intensity = 0xC8};
  m.bytes[0] = 0x61;
  m.bytes[1] = 0x62;
  m.bytes[2] = 0x63;
  m.bytes[3] = 0x64;
  return m;
}

// player_fiducial_msg_t placed at `at` (38 bytes): target_id @+0, bytes @+4, len @+36, intensity @+37.
void put_four_byte_msg(WireBytes& w, std::size_t at) {
  w.at(at + 0, {0xFE, 0xFD, 0xFC, 0xFB})    // target_id int32 = ~0x01020304
      .at(at + 4, {0x61, 0x62, 0x63, 0x64})  // bytes[0..3]
      .zeros(at + 8, 28)                     // bytes[4..31]
      .at(at + 36, {0x04})                   // len = 4
      .at(at + 37, {0xC8});                  // intensity
}

TEST(FiducialGolden, Message) {
  WireBytes w(38);
  put_four_byte_msg(w, 0);
  const Bytes golden_bytes = w.done();
  EXPECT_TRUE(MatchesGolden(four_byte_msg(), golden_bytes));
  const auto j = to_json(four_byte_msg());
  EXPECT_TRUE(golden::HasFields(j, {"target_id", "bytes", "len", "intensity"}));
  EXPECT_EQ(j.at("target_id"), -0x01020305);
  EXPECT_EQ(j.at("bytes"), (nlohmann::json{0x61, 0x62, 0x63, 0x64}));
  EXPECT_TRUE(Rejects<FiducialMsg>(golden::drop_last(golden_bytes), "intensity", 38, 37));
  Bytes too_long = golden_bytes;
  too_long[36] = 33;  // len @36 = 33 > PLAYER_FIDUCIAL_MAX_MSG_LEN (the count follows its array)
  EXPECT_TRUE(Rejects<FiducialMsg>(too_long, "bytes", 32, 33));
}

TEST(FiducialGolden, ReceiveRequest) {
  const FiducialMsgRxRequest value{.subtype = kFiducialRecvMsg, .consume = 1};
  EXPECT_TRUE(MatchesGolden(value, Bytes{0x05,     // subtype @0 = PLAYER_FIDUCIAL_RECV_MSG (5)
                                         0x01}));  // consume @1
  EXPECT_TRUE(Rejects<FiducialMsgRxRequest>(Bytes{0x05}, "consume", 2, 1));
}

Bytes send_request_bytes() {
  WireBytes w(40);
  w.at(0, {0x04})       // subtype @0 uint8 = PLAYER_FIDUCIAL_SEND_MSG (4)
      .at(1, {0x01});   // consume @1 uint8
  put_four_byte_msg(w, 2);  // msg @2, 38 bytes: target_id @2, bytes @6, len @38, intensity @39
  return w.done();
}

TEST(FiducialGolden, SendRequest) {
  const FiducialMsgTxRequest value{.subtype = kFiducialSendMsg, .consume = 1, .msg = four_byte_msg()};
  EXPECT_TRUE(MatchesGolden(value, send_request_bytes()));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "consume", "msg"}));
  EXPECT_EQ(j.at("msg").at("len"), 4);
  EXPECT_TRUE(Rejects<FiducialMsgTxRequest>(golden::drop_last(send_request_bytes()), "msg", 40, 39));
  EXPECT_TRUE(Rejects<FiducialMsgTxRequest>(golden::with_extra_byte(send_request_bytes()), "", 40, 41));
}

// msg.len is a count like any other: a 33-byte message cannot fit bytes[32],
// whether player_fiducial_msg_t stands alone (rejected above) or is embedded.
TEST(FiducialGolden, SendRequestWithMessageLengthLargerThan32IsRejected) {
  Bytes bytes = send_request_bytes();
  bytes[38] = 33;  // msg.len @2+36 = 33
  EXPECT_THROW((void)decode<FiducialMsgTxRequest>(bytes), DecodeError);
}

TEST(FiducialGolden, ExchangeRequest) {
  const FiducialMsgTxRxRequest value{
      .subtype = kFiducialExchangeMsg, .msg = four_byte_msg(), .consume_send = 0x01, .consume_reply = 0x02};
  WireBytes w(41);
  w.at(0, {0x06});          // subtype       @0  uint8 = PLAYER_FIDUCIAL_EXCHANGE_MSG (6)
  put_four_byte_msg(w, 1);  // msg           @1  38 bytes: target_id @1, bytes @5, len @37, intensity @38
  w.at(39, {0x01})          // consume_send  @39 uint8
      .at(40, {0x02});      // consume_reply @40 uint8
  const Bytes golden_bytes = w.done();
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_TRUE(golden::HasFields(to_json(value), {"subtype", "msg", "consume_send", "consume_reply"}));
  EXPECT_TRUE(Rejects<FiducialMsgTxRxRequest>(golden::drop_last(golden_bytes), "consume_reply", 41, 40));
  EXPECT_TRUE(Rejects<FiducialMsgTxRxRequest>(Bytes(golden_bytes.begin(), golden_bytes.begin() + 38), "msg", 41, 38));
}

}  // namespace fiducial_test
}  // namespace playerkit::protocol
