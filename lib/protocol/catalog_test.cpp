#include "protocol/catalog.hpp"

#include <map>
#include <set>

#include <gtest/gtest.h>

#include "protocol/interfaces.hpp"
#include "protocol/messages/all.hpp"
#include "protocol/payload_json.hpp"

namespace playerkit::protocol {
namespace catalog_test {

using nlohmann::json;

std::vector<const PayloadCodec*> codecs_of(const InterfaceMessages& m) {
  std::vector<const PayloadCodec*> out{m.data, m.command};
  for (const auto& kind : m.requests) {
    out.push_back(kind.request);
    out.push_back(kind.reply);
  }
  std::erase(out, nullptr);
  return out;
}

TEST(Catalog, CoversEveryInterface) {
  for (const auto& info : all_interfaces()) {
    const auto* m = find_messages(info.code);
    ASSERT_NE(m, nullptr) << info.name;
    EXPECT_EQ(m->subtype_size, info.code == kPlayerCode ? 2u : 1u);
  }
  EXPECT_EQ(find_messages(19), nullptr);
}

TEST(Catalog, RequestNamesAndSubtypesAreUniquePerInterface) {
  std::size_t total = 0;
  for (const auto& m : all_messages()) {
    std::set<std::string_view> names;
    std::set<std::uint16_t> subtypes;
    for (const auto& kind : m.requests) {
      EXPECT_TRUE(names.insert(kind.name).second) << interface_name(m.interface) << " " << kind.name;
      EXPECT_TRUE(subtypes.insert(kind.subtype).second) << interface_name(m.interface) << " " << kind.name;
      EXPECT_EQ(m.find_request(kind.name), &kind);
      EXPECT_FALSE(kind.summary.empty());
      if (kind.form == RequestForm::kStruct) {
        EXPECT_NE(kind.request, nullptr) << kind.name;
      }
      ++total;
    }
  }
  // One kind per request subtype constant of wire-format.md §5 (idar and idarturret
  // share theirs; audiomixer has no constant, its driver takes any byte).
  const std::map<std::uint16_t, std::size_t> expected{
      {kPlayerCode, 8}, {kPowerCode, 1},  {kPositionCode, 16}, {kPosition3dCode, 4}, {kSonarCode, 2},
      {kLaserCode, 4},  {kBlobfinderCode, 2}, {kPtzCode, 2},   {kAudiodspCode, 2},  {kAudiomixerCode, 1},
      {kFiducialCode, 6}, {kBumperCode, 1}, {kTruthCode, 5},   {kIdarCode, 4},      {kIdarturretCode, 4},
      {kWifiCode, 4},   {kIrCode, 2},       {kLocalizeCode, 5}, {kMcomCode, 5}};
  std::size_t expected_total = 0;
  for (const auto& [code, count] : expected) {
    EXPECT_EQ(find_messages(code)->requests.size(), count) << interface_name(code);
    expected_total += count;
  }
  EXPECT_EQ(total, expected_total);
}

TEST(Catalog, EveryCodecRoundTripsAValueThroughJsonAndBytes) {
  for (const auto& m : all_messages()) {
    for (const auto* codec : codecs_of(m)) {
      SCOPED_TRACE(std::string(codec->wire_name));
      const auto bytes = codec->from_json(json::object());
      EXPECT_GE(bytes.size(), codec->min_size);
      EXPECT_LE(bytes.size(), codec->max_size);
      const json j = codec->to_json(bytes);
      EXPECT_EQ(codec->from_json(j), bytes);
    }
  }
}

TEST(RequestPayload, QueryIsOnlyTheSubtype) {
  const auto& laser = *find_messages(kLaserCode);
  EXPECT_EQ(request_payload(laser, *laser.find_request("get-geom"), json::object()),
            (std::vector<std::uint8_t>{0x01}));
  const auto& player = *find_messages(kPlayerCode);
  EXPECT_EQ(request_payload(player, *player.find_request("devlist"), nullptr),
            (std::vector<std::uint8_t>{0x00, 0x01}));
  EXPECT_THROW(request_payload(laser, *laser.find_request("get-geom"), json{{"pose", {1, 2, 3}}}),
               JsonError);
}

TEST(RequestPayload, StructRequestGetsItsSubtypeFromTheName) {
  const auto& position = *find_messages(kPositionCode);
  const auto bytes =
      request_payload(position, *position.find_request("set-odom"), json{{"x", 1000}, {"theta", -90}});
  EXPECT_EQ(bytes, (std::vector<std::uint8_t>{9, 0, 0, 0x03, 0xE8, 0, 0, 0, 0, 0xFF, 0xFF, 0xFF, 0xA6}));
  const auto& player = *find_messages(kPlayerCode);
  const auto dev = request_payload(player, *player.find_request("dev"),
                                   json{{"code", 6}, {"index", 0}, {"access", 'r'}});
  EXPECT_EQ(dev, (std::vector<std::uint8_t>{0, 3, 0, 6, 0, 0, 'r'}));
}

TEST(PayloadJson, RequestsAndRepliesPickTheirStructBySubtype) {
  const json query = payload_to_json(kLaserCode, MessageType::kRequest, std::vector<std::uint8_t>{1});
  EXPECT_EQ(query, json::parse(R"({"subtype":1})"));
  LaserGeom geom;
  geom.subtype = kLaserGetGeom;
  geom.pose = {100, 0, 0};
  geom.size = {155, 155};
  const auto reply = encode(geom);
  EXPECT_EQ(payload_to_json(kLaserCode, MessageType::kAck, reply), to_json(geom));
  // The power reply is a data packet without a subtype: the request says what it is.
  PowerData power;
  power.charge = 127;
  EXPECT_EQ(payload_to_json(kPowerCode, MessageType::kAck, encode(power), kMainPowerReq), to_json(power));
  EXPECT_EQ(payload_to_json(kLaserCode, MessageType::kNack, {}), json::object());
}

TEST(PayloadJson, UnknownShapesBecomeRawBytesAndBack) {
  const std::vector<std::uint8_t> odd{0x63, 0x01, 0x02};
  const json j = payload_to_json(kLaserCode, MessageType::kRequest, odd);
  EXPECT_EQ(j, json::parse(R"({"raw":[99,1,2]})"));
  EXPECT_EQ(payload_from_json(kLaserCode, MessageType::kRequest, j), odd);
  EXPECT_EQ(payload_to_json(kNullCode, MessageType::kData, odd), j);
  EXPECT_THROW(payload_from_json(kLaserCode, MessageType::kData, json::parse(R"({"raw":[256]})")), JsonError);
}

TEST(PayloadJson, DataAndCommandsRoundTrip) {
  PositionCommand cmd;
  cmd.xspeed = 200;
  cmd.yawspeed = -10;
  const auto bytes = encode(cmd);
  const json j = payload_to_json(kPositionCode, MessageType::kCommand, bytes);
  EXPECT_EQ(j["xspeed"], 200);
  EXPECT_EQ(payload_from_json(kPositionCode, MessageType::kCommand, j), bytes);
  EXPECT_THROW(payload_to_json(kLaserCode, MessageType::kData, std::vector<std::uint8_t>(10)), DecodeError);
}

}  // namespace catalog_test
}  // namespace playerkit::protocol
