// Golden-byte tests of the `wifi` interface (wire-format.md §5 "wifi").

#include "protocol/messages/wifi.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/golden_test_util.hpp"

namespace playerkit::protocol {
namespace wifi_test {

using golden::Bytes;
using golden::DecodesTo;
using golden::EncodesTo;
using golden::MatchesGolden;
using golden::Rejects;
using golden::SurvivesJson;
using golden::WireBytes;

static_assert(WifiMacRequest::kWireSize == 1);         // player_wifi_mac_req_t
static_assert(WifiIwspyAddrRequest::kWireSize == 33);  // player_wifi_iwspy_addr_req_t
static_assert(WifiLink::kWireSize == 38);              // player_wifi_link_t
static_assert(WifiData::kWireSize == 658);             // player_wifi_data_t

TEST(WifiGolden, MacRequest) {
  EXPECT_TRUE(MatchesGolden(WifiMacRequest{.subtype = kWifiMacReq}, Bytes{0x01}));  // subtype @0 = PLAYER_WIFI_MAC_REQ
  EXPECT_TRUE(Rejects<WifiMacRequest>(golden::kEmpty, "subtype", 1, 0));
  EXPECT_TRUE(Rejects<WifiMacRequest>(Bytes{0x01, 0x00}, "", 1, 2));
}

TEST(WifiGolden, IwspyAddressRequest) {
  const WifiIwspyAddrRequest value{.subtype = kWifiIwspyAddReq, .address = "192.168.0.7"};
  const Bytes golden_bytes = WireBytes(33)
                                 .at(0, {0x0A})               // subtype @0 uint8 = PLAYER_WIFI_IWSPY_ADD_REQ (10)
                                 .text(1, "192.168.0.7", 32)  // address @1 char[32]
                                 .done();
  EXPECT_TRUE(MatchesGolden(value, golden_bytes));
  EXPECT_EQ(to_json(value).at("address"), "192.168.0.7");
  EXPECT_TRUE(Rejects<WifiIwspyAddrRequest>(golden::drop_last(golden_bytes), "address", 33, 32));
}

const WifiLink kLinkA{.ip = "10.0.0.2", .qual = 0x0102, .level = 0x0304, .noise = 0x0506};
const WifiLink kLinkB{.ip = "10.0.0.3", .qual = 0x1112, .level = 0x1314, .noise = 0x1516};

// player_wifi_link_t at `at` (38 bytes): ip @+0 char[32], qual @+32, level @+34, noise @+36.
void put_link(WireBytes& w, std::size_t at, std::string_view ip, std::initializer_list<std::uint8_t> qual_level_noise) {
  w.text(at, ip, 32).at(at + 32, qual_level_noise);
}

TEST(WifiGolden, Link) {
  WireBytes w(38);
  put_link(w, 0, "10.0.0.2", {0x01, 0x02, 0x03, 0x04, 0x05, 0x06});
  EXPECT_TRUE(MatchesGolden(kLinkA, w.done()));
  EXPECT_TRUE(golden::HasFields(to_json(kLinkA), {"ip", "qual", "level", "noise"}));
}

WifiData two_links() {
  WifiData d{.link_count = 2,
             .throughput = 0x21222324,
             .bitrate = ~0x31323334,
             .mode = kWifiModeInfra,
             .qual_type = kWifiQualDbm,
             .maxqual = 0x4142,
             .maxlevel = 0x4344,
             .maxnoise = 0x4546,
             .ap = "00:11:22:33:44:55"};
  d.links[0] = kLinkA;
  d.links[1] = kLinkB;
  return d;
}

Bytes two_links_bytes() {
  WireBytes w(658);
  put_link(w, 0, "10.0.0.2", {0x01, 0x02, 0x03, 0x04, 0x05, 0x06});   // links[0] @0
  put_link(w, 38, "10.0.0.3", {0x11, 0x12, 0x13, 0x14, 0x15, 0x16});  // links[1] @38
  w.zeros(76, 14 * 38)                       // links[2..15] @76..607
      .at(608, {0x00, 0x02})                 // link_count @608 uint16 = 2 (after the array)
      .at(610, {0x21, 0x22, 0x23, 0x24})     // throughput @610 uint32
      .at(614, {0xCE, 0xCD, 0xCC, 0xCB})     // bitrate    @614 int32 = ~0x31323334
      .at(618, {0x03})                       // mode       @618 uint8 = PLAYER_WIFI_MODE_INFRA
      .at(619, {0x01})                       // qual_type  @619 uint8 = PLAYER_WIFI_QUAL_DBM
      .at(620, {0x41, 0x42})                 // maxqual    @620 uint16
      .at(622, {0x43, 0x44})                 // maxlevel   @622 uint16
      .at(624, {0x45, 0x46})                 // maxnoise   @624 uint16
      .text(626, "00:11:22:33:44:55", 32);   // ap         @626 char[32]
  return w.done();
}

TEST(WifiGolden, DataPacket) {
  EXPECT_TRUE(EncodesTo(two_links(), two_links_bytes()));
  EXPECT_TRUE(DecodesTo(two_links_bytes(), two_links()));
}

TEST(WifiGolden, DataJson) {
  const auto j = to_json(two_links());
  EXPECT_TRUE(golden::HasFields(j, {"links", "link_count", "throughput", "bitrate", "mode", "qual_type", "maxqual",
                                    "maxlevel", "maxnoise", "ap"}));
  ASSERT_EQ(j.at("links").size(), 2u);
  EXPECT_EQ(j.at("links")[1].at("ip"), "10.0.0.3");
  EXPECT_EQ(j.at("bitrate"), -0x31323335);
  EXPECT_EQ(j.at("ap"), "00:11:22:33:44:55");
  EXPECT_TRUE(SurvivesJson(two_links()));
}

TEST(WifiGolden, DataCountAndLengthAreChecked) {
  Bytes bytes = two_links_bytes();
  bytes[609] = 17;  // link_count @608 = 17 > PLAYER_WIFI_MAX_LINKS
  EXPECT_TRUE(Rejects<WifiData>(bytes, "links", 16, 17));
  EXPECT_TRUE(Rejects<WifiData>(golden::drop_last(two_links_bytes()), "ap", 658, 657));
  EXPECT_TRUE(Rejects<WifiData>(Bytes(600, 0), "links", 658, 600));
  EXPECT_TRUE(Rejects<WifiData>(golden::with_extra_byte(two_links_bytes()), "", 658, 659));
}

}  // namespace wifi_test
}  // namespace playerkit::protocol
