#include "protocol/message_json.hpp"

#include <gtest/gtest.h>

#include <string>

#include "protocol/binary_codec.hpp"
#include "protocol/errors.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/all.hpp"

namespace playerkit::protocol {
namespace message_json_test {

using nlohmann::json;

Message laser_message() {
  LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 100;
  scan.range_res = 1;
  scan.range_count = 181;
  for (std::size_t i = 0; i < 181; ++i) scan.ranges[i] = static_cast<std::uint16_t>(1000 + i);
  Message m;
  m.header = make_header(MessageType::kData, {kLaserCode, 0}, {1086000000, 250000}, {1086000000, 200000});
  m.payload = encode(scan);
  m.header.size = static_cast<std::uint32_t>(m.payload.size());
  return m;
}

TEST(MessageJson, LaserDataRoundTripsExactly) {
  const Message m = laser_message();
  const json j = message_to_json(m);
  EXPECT_EQ(j["type"], "data");
  EXPECT_EQ(j["device"], "laser");
  EXPECT_EQ(j["index"], 0);
  EXPECT_DOUBLE_EQ(j["time"].get<double>(), 1086000000.25);
  EXPECT_EQ(j["data"]["ranges"].size(), 181u);
  const Message back = message_from_json(json::parse(j.dump()));
  EXPECT_EQ(back, m);
}

TEST(MessageJson, RequestsCarryTheirName) {
  Message req;
  req.header = make_header(MessageType::kRequest, {kLaserCode, 0}, {}, {});
  req.payload = {kLaserGetGeom};
  req.header.size = 1;
  const json j = message_to_json(req);
  EXPECT_EQ(j["request"], "get-geom");
  EXPECT_EQ(message_from_json(j), req);

  const Message from_name = message_from_json(
      json::parse(R"({"type":"req","device":"position","request":"set-odom","data":{"x":5}})"));
  EXPECT_EQ(from_name.payload.size(), 13u);
  EXPECT_EQ(from_name.payload[0], kPositionSetOdomReq);
}

TEST(MessageJson, AnInterfaceWithoutANameKeepsItsCodeAndComesBack) {
  // Found by the json_line fuzzer: "interface 73" could not be read back.
  Message m;
  m.header = make_header(MessageType::kCommand, {73, 2}, {}, {});
  m.payload = {0};
  m.header.size = 1;
  const json j = message_to_json(m);
  EXPECT_EQ(j["device"], 73);
  EXPECT_EQ(j["index"], 2);
  EXPECT_EQ(message_from_json(json::parse(j.dump())), m);
}

TEST(MessageJson, ARequestCutShortAfterItsSubtypeComesBackAsJustTheSubtype) {
  // Found by the json_line fuzzer: idarturret's request struct has no
  // "subtype" field, so {"subtype":0} was refused on the way back.
  Message m;
  m.header = make_header(MessageType::kRequest, {kIdarturretCode, 0}, {}, {});
  m.payload = {0};
  m.header.size = 1;
  const json j = message_to_json(m);
  EXPECT_EQ(j["data"], (json{{"subtype", 0}}));
  EXPECT_EQ(message_from_json(json::parse(j.dump())), m);
  // Other fields beside it still go through the request's struct.
  EXPECT_THROW(message_from_json(json::parse(
                   R"({"type":"req","device":"idarturret","data":{"subtype":0,"bogus":1}})")),
               JsonError);
}

TEST(MessageJson, ClearErrors) {
  EXPECT_THROW(message_from_json(json::parse(R"({"device":"laser"})")), JsonError);
  EXPECT_THROW(message_from_json(json::parse(R"({"type":"data","device":"lazer"})")), JsonError);
  EXPECT_THROW(message_from_json(json::parse(R"({"type":"dta","device":"laser"})")), JsonError);
  EXPECT_THROW(message_from_json(json::parse(R"({"type":"req","device":"laser","request":"fly"})")), JsonError);
}

TEST(MessageJson, IndexAndRequestOfTheWrongKindAreJsonErrors) {
  // Hand-written JSON (player-send --stdin): each is named, none wraps or is cut.
  const auto error_of = [](const char* text) -> std::string {
    try {
      (void)message_from_json(json::parse(text));
    } catch (const JsonError& e) {
      return e.what();
    }
    return "no JsonError";
  };
  EXPECT_EQ(error_of(R"({"type":"data","device":"power","index":70000})"),
            "message: \"index\" must be a whole number from 0 to 65535, got 70000");
  EXPECT_EQ(error_of(R"({"type":"data","device":"power","index":1.5})"),
            "message: \"index\" must be a whole number from 0 to 65535, got 1.5");
  EXPECT_EQ(error_of(R"({"type":"data","device":"power","index":"2"})"),
            "message: \"index\" must be a whole number from 0 to 65535, got \"2\"");
  EXPECT_EQ(error_of(R"({"type":"req","device":"laser","request":5})"),
            "message: \"request\" must be a request's name, got 5");
  EXPECT_EQ(message_from_json(json::parse(R"({"type":"data","device":"power","index":65535})")).device().index,
            65535);
}

TEST(MessageJson, TimesPastTheHeaderFieldsAreRefused) {
  EXPECT_THROW(message_from_json(json::parse(R"({"type":"data","device":"power","time":4294967296.5})")), JsonError);
  EXPECT_THROW(message_from_json(json::parse(R"({"type":"data","device":"power","timestamp":1e12})")), JsonError);
  const Message latest =
      message_from_json(json::parse(R"({"type":"data","device":"power","time":4294967295.999999})"));
  EXPECT_EQ(latest.time(), (Timestamp{0xFFFFFFFF, 999999}));
}

}  // namespace message_json_test
}  // namespace playerkit::protocol
