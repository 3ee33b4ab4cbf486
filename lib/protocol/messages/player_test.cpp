// Golden-byte tests of the `player` device payloads (wire-format.md §5 "player").
// Subtypes of this device are uint16, unlike every other interface.

#include "protocol/messages/player.hpp"

#include <gtest/gtest.h>

#include "protocol/constants.hpp"
#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace player_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(DeviceId::kWireSize == 6);                // player_device_id_t
static_assert(DeviceList::kWireSize == 388);            // player_device_devlist_t
static_assert(DriverInfo::kWireSize == 72);             // player_device_driverinfo_t
static_assert(DeviceAccessRequest::kWireSize == 7);     // player_device_req_t
static_assert(DeviceAccessReply::kWireSize == 71);      // player_device_resp_t
static_assert(DataRequest::kWireSize == 2);             // player_device_data_req_t
static_assert(DataModeRequest::kWireSize == 3);         // player_device_datamode_req_t
static_assert(DataFrequencyRequest::kWireSize == 4);    // player_device_datafreq_req_t
static_assert(AuthRequest::kWireSize == 34);            // player_device_auth_req_t
static_assert(NameServiceRequest::kWireSize == 68);     // player_device_nameservice_req_t

TEST(PlayerGolden, DeviceId) {
  const DeviceId value{.code = 0x0102, .index = 0x0304, .port = 0x0506};
  const Bytes golden_bytes{0x01, 0x02,   // code  @0 uint16
                           0x03, 0x04,   // index @2 uint16
                           0x05, 0x06};  // port  @4 uint16
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  EXPECT_TRUE(SurvivesJson(value));
}

DeviceList three_devices() {
  DeviceList list{.subtype = kPlayerDevlistReq, .device_count = 3};
  list.devices[0] = {.code = 6, .index = 2, .port = 6665};
  list.devices[1] = {.code = 4, .index = 1, .port = 6666};
  list.devices[2] = {.code = 0x0102, .index = 0x0304, .port = 0x0506};
  return list;
}

Bytes three_devices_bytes() {
  return WireBytes(388)
      .at(0, {0x00, 0x01})  // subtype      @0 uint16 = PLAYER_PLAYER_DEVLIST_REQ (1)
      .at(2, {0x00, 0x03})  // device_count @2 uint16 = 3
      // devices @4, 6 bytes each: code, index, port
      .at(4, {0x00, 0x06, 0x00, 0x02, 0x1A, 0x09})   // devices[0] @4  laser:2 port 6665
      .at(10, {0x00, 0x04, 0x00, 0x01, 0x1A, 0x0A})  // devices[1] @10 position:1 port 6666
      .at(16, {0x01, 0x02, 0x03, 0x04, 0x05, 0x06})  // devices[2] @16
      .zeros(22, 61 * 6)                              // devices[3..63] @22..387 unused, zero
      .done();
}

TEST(PlayerGolden, DeviceListReplyIsAlwaysTheFull388Bytes) {
  EXPECT_TRUE(EncodesTo(three_devices(), three_devices_bytes()));
  EXPECT_TRUE(DecodesTo(three_devices_bytes(), three_devices()));
}

TEST(PlayerGolden, DeviceListJsonShowsOnlyTheCountedDevices) {
  const auto j = to_json(three_devices());
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "device_count", "devices"}));
  EXPECT_EQ(j.at("device_count"), 3);
  ASSERT_EQ(j.at("devices").size(), 3u);
  EXPECT_EQ(j.at("devices")[0].at("code"), 6);
  EXPECT_EQ(j.at("devices")[0].at("port"), 6665);
  EXPECT_EQ(j.at("devices")[2].at("index"), 0x0304);
  EXPECT_TRUE(SurvivesJson(three_devices()));

  // Entries past device_count are not part of the JSON, so they do not survive it.
  DeviceList stale = three_devices();
  stale.devices[5] = {.code = 9, .index = 9, .port = 9};
  EXPECT_EQ(to_json(stale), j);
  EXPECT_EQ(from_json<DeviceList>(to_json(stale)), three_devices());
}

TEST(PlayerGolden, DeviceListCountLargerThan64IsRejected) {
  Bytes bytes = three_devices_bytes();
  bytes[2] = 0x00;
  bytes[3] = 65;  // device_count @2 = 65 > PLAYER_MAX_DEVICES
  EXPECT_TRUE(Rejects<DeviceList>(bytes, "devices", 64, 65));
  bytes[3] = 64;  // a full list is fine
  EXPECT_TRUE(golden::Accepts<DeviceList>(bytes));
}

TEST(PlayerGolden, DeviceListTruncatedOrOversizedIsRejected) {
  const Bytes bytes = three_devices_bytes();
  EXPECT_TRUE(Rejects<DeviceList>(golden::drop_last(bytes), "devices", 388, 387));
  EXPECT_TRUE(Rejects<DeviceList>(golden::kEmpty, "subtype", 388, 0));
  EXPECT_TRUE(Rejects<DeviceList>(Bytes{0x00, 0x01, 0x00}, "device_count", 388, 3));
  EXPECT_TRUE(Rejects<DeviceList>(golden::with_extra_byte(bytes), "", 388, 389));
}

DriverInfo sick_driver_info() {
  return {.subtype = kPlayerDriverinfoReq,
          .id = {.code = 0x0006, .index = 0x0102, .port = 0x1A09},
          .driver_name = "sicklms200"};
}

Bytes sick_driver_info_bytes() {
  return WireBytes(72)
      .at(0, {0x00, 0x02})               // subtype     @0 uint16 = PLAYER_PLAYER_DRIVERINFO_REQ (2)
      .at(2, {0x00, 0x06})               // id.code     @2 uint16
      .at(4, {0x01, 0x02})               // id.index    @4 uint16
      .at(6, {0x1A, 0x09})               // id.port     @6 uint16 = 6665
      .text(8, "sicklms200", 64)         // driver_name @8 char[64], NUL padded
      .done();
}

TEST(PlayerGolden, DriverInfo) {
  EXPECT_TRUE(EncodesTo(sick_driver_info(), sick_driver_info_bytes()));
  EXPECT_TRUE(DecodesTo(sick_driver_info_bytes(), sick_driver_info()));
  const auto j = to_json(sick_driver_info());
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "id", "driver_name"}));
  EXPECT_EQ(j.at("driver_name"), "sicklms200");
  EXPECT_EQ(j.at("id").at("port"), 6665);
  EXPECT_TRUE(SurvivesJson(sick_driver_info()));
  EXPECT_TRUE(Rejects<DriverInfo>(golden::drop_last(sick_driver_info_bytes()), "driver_name", 72, 71));
  EXPECT_TRUE(Rejects<DriverInfo>(Bytes{0x00, 0x02, 0x00, 0x06}, "id", 72, 4));
  EXPECT_TRUE(Rejects<DriverInfo>(golden::with_extra_byte(sick_driver_info_bytes()), "", 72, 73));
}

TEST(PlayerGolden, DeviceAccessRequest) {
  const DeviceAccessRequest value{.subtype = kPlayerDevReq, .code = 0x0102, .index = 0x0304, .access = 'a'};
  const Bytes golden_bytes{0x00, 0x03,  // subtype @0 uint16 = PLAYER_PLAYER_DEV_REQ (3)
                           0x01, 0x02,  // code    @2 uint16
                           0x03, 0x04,  // index   @4 uint16
                           0x61};       // access  @6 uint8 = 'a'
  static_assert(DeviceAccessRequest::kWireSize == 7);
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  EXPECT_EQ(to_json(value).at("access"), 0x61);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<DeviceAccessRequest>(golden::drop_last(golden_bytes), "access", 7, 6));
  EXPECT_TRUE(Rejects<DeviceAccessRequest>(golden::kEmpty, "subtype", 7, 0));
  EXPECT_TRUE(Rejects<DeviceAccessRequest>(golden::with_extra_byte(golden_bytes), "", 7, 8));
}

TEST(PlayerGolden, DeviceAccessReply) {
  // Driver names are bytes; one above 0x7F shows the Latin-1 mapping of the JSON codec.
  const DeviceAccessReply value{
      .subtype = kPlayerDevReq, .code = 0x0028, .index = 0x0304, .access = 'e', .driver_name = "cam\xE9ra"};
  const Bytes golden_bytes = WireBytes(71)
                                 .at(0, {0x00, 0x03})  // subtype     @0 uint16
                                 .at(2, {0x00, 0x28})  // code        @2 uint16 = 40 (camera)
                                 .at(4, {0x03, 0x04})  // index       @4 uint16
                                 .at(6, {0x65})        // access      @6 uint8 = 'e'
                                 .at(7, {'c', 'a', 'm', 0xE9, 'r', 'a'})  // driver_name @7 uint8[64]
                                 .zeros(13, 58)                           //   NUL padding to @70
                                 .done();
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "code", "index", "access", "driver_name"}));
  EXPECT_EQ(j.at("driver_name"), "cam\u00E9ra");
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<DeviceAccessReply>(golden::drop_last(golden_bytes), "driver_name", 71, 70));
  EXPECT_TRUE(Rejects<DeviceAccessReply>(golden::with_extra_byte(golden_bytes), "", 71, 72));
}

TEST(PlayerGolden, DataRequestDataModeAndDataFrequency) {
  const DataRequest data{.subtype = kPlayerDataReq};
  const Bytes data_bytes{0x00, 0x04};  // subtype @0 uint16 = PLAYER_PLAYER_DATA_REQ (4)
  EXPECT_TRUE(EncodesTo(data, data_bytes));
  EXPECT_TRUE(DecodesTo(data_bytes, data));
  EXPECT_TRUE(Rejects<DataRequest>(Bytes{0x00}, "subtype", 2, 1));
  EXPECT_TRUE(Rejects<DataRequest>(Bytes{0x00, 0x04, 0x00}, "", 2, 3));

  const DataModeRequest mode{.subtype = kPlayerDatamodeReq, .mode = 3};
  const Bytes mode_bytes{0x00, 0x05,  // subtype @0 uint16 = PLAYER_PLAYER_DATAMODE_REQ (5)
                         0x03};       // mode    @2 uint8  = PULL_NEW
  EXPECT_TRUE(EncodesTo(mode, mode_bytes));
  EXPECT_TRUE(DecodesTo(mode_bytes, mode));
  EXPECT_TRUE(Rejects<DataModeRequest>(golden::drop_last(mode_bytes), "mode", 3, 2));
  EXPECT_TRUE(Rejects<DataModeRequest>(golden::with_extra_byte(mode_bytes), "", 3, 4));

  const DataFrequencyRequest freq{.subtype = kPlayerDatafreqReq, .frequency = 0x0102};
  const Bytes freq_bytes{0x00, 0x06,  // subtype   @0 uint16 = PLAYER_PLAYER_DATAFREQ_REQ (6)
                         0x01, 0x02};  // frequency @2 uint16
  EXPECT_TRUE(EncodesTo(freq, freq_bytes));
  EXPECT_TRUE(DecodesTo(freq_bytes, freq));
  EXPECT_EQ(to_json(freq).at("frequency"), 0x0102);
  EXPECT_TRUE(SurvivesJson(freq));
  EXPECT_TRUE(Rejects<DataFrequencyRequest>(golden::drop_last(freq_bytes), "frequency", 4, 3));
}

TEST(PlayerGolden, AuthRequest) {
  const AuthRequest value{.subtype = kPlayerAuthReq, .auth_key = "s3cr3t"};
  const Bytes golden_bytes = WireBytes(34)
                                 .at(0, {0x00, 0x07})      // subtype  @0 uint16 = PLAYER_PLAYER_AUTH_REQ (7)
                                 .text(2, "s3cr3t", 32)    // auth_key @2 uint8[32], NUL padded
                                 .done();
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  EXPECT_EQ(to_json(value).at("auth_key"), "s3cr3t");
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<AuthRequest>(golden::drop_last(golden_bytes), "auth_key", 34, 33));
  EXPECT_TRUE(Rejects<AuthRequest>(golden::with_extra_byte(golden_bytes), "", 34, 35));
}

// A client may fill all 32 key bytes (the 1.5 server then forces the last one to
// NUL). decode accepts such a payload; the JSON codec promises that any byte
// sequence of a text field survives a round trip.
TEST(PlayerGolden, AuthKeyFillingAll32BytesSurvivesJson) {
  Bytes bytes(34, 'k');
  bytes[0] = 0x00;
  bytes[1] = 0x07;
  const AuthRequest decoded = decode<AuthRequest>(bytes);
  EXPECT_EQ(decoded.auth_key.view().size(), 32u);
  EXPECT_TRUE(SurvivesJson(decoded));
}

TEST(PlayerGolden, NameServiceRequest) {
  const NameServiceRequest value{.subtype = kPlayerNameserviceReq, .name = "robot-1", .port = 0x1A0B};
  const Bytes golden_bytes = WireBytes(68)
                                 .at(0, {0x00, 0x08})     // subtype @0  uint16 = PLAYER_PLAYER_NAMESERVICE_REQ (8)
                                 .text(2, "robot-1", 64)  // name    @2  uint8[64]
                                 .at(66, {0x1A, 0x0B})    // port    @66 uint16 = 6667
                                 .done();
  EXPECT_TRUE(EncodesTo(value, golden_bytes));
  EXPECT_TRUE(DecodesTo(golden_bytes, value));
  const auto j = to_json(value);
  EXPECT_TRUE(golden::HasFields(j, {"subtype", "name", "port"}));
  EXPECT_EQ(j.at("name"), "robot-1");
  EXPECT_EQ(j.at("port"), 6667);
  EXPECT_TRUE(SurvivesJson(value));
  EXPECT_TRUE(Rejects<NameServiceRequest>(golden::drop_last(golden_bytes), "port", 68, 67));
  EXPECT_TRUE(Rejects<NameServiceRequest>(Bytes(golden_bytes.begin(), golden_bytes.begin() + 65), "name", 68, 65));
  EXPECT_TRUE(Rejects<NameServiceRequest>(golden::with_extra_byte(golden_bytes), "", 68, 69));
}

}  // namespace player_test
}  // namespace playerkit::protocol
