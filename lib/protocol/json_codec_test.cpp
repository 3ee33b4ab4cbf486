#include "protocol/json_codec.hpp"

#include <gtest/gtest.h>

#include "protocol/messages/all.hpp"

namespace playerkit::protocol {
namespace json_codec_test {

using nlohmann::json;

TEST(JsonCodec, UsesSpecFieldNamesAndShowsOnlyCountedElements) {
  LaserData scan;
  scan.min_angle = -9000;
  scan.max_angle = 9000;
  scan.resolution = 100;
  scan.range_res = 1;
  scan.range_count = 2;
  scan.ranges = {1500, 2500, 7777};  // the third is beyond range_count
  scan.intensity = {1, 0};
  const json j = to_json(scan);
  EXPECT_EQ(j, json::parse(R"({"min_angle":-9000,"max_angle":9000,"resolution":100,"range_res":1,
                              "range_count":2,"ranges":[1500,2500],"intensity":[1,0]})"));
}

TEST(JsonCodec, MissingFieldsAreZeroAndMissingCountFollowsTheArray) {
  const auto scan = from_json<LaserData>(json::parse(R"({"ranges":[10,20,30]})"));
  EXPECT_EQ(scan.range_count, 3);
  EXPECT_EQ(scan.ranges[2], 30);
  EXPECT_EQ(scan.ranges[3], 0);
  EXPECT_EQ(scan.min_angle, 0);
}

TEST(JsonCodec, ExplicitCountIsKept) {
  const auto scan = from_json<LaserData>(json::parse(R"({"range_count":1,"ranges":[10,20]})"));
  EXPECT_EQ(scan.range_count, 1);
}

TEST(JsonCodec, UnknownFieldIsAnErrorListingTheKnownOnes) {
  try {
    (void)from_json<PositionCommand>(json::parse(R"({"xspeed":200,"speed":1})"));
    FAIL();
  } catch (const JsonError& e) {
    EXPECT_NE(std::string(e.what()).find("player_position_cmd_t: unknown field 'speed'"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("yawspeed"), std::string::npos);
  }
}

TEST(JsonCodec, OutOfRangeAndWrongTypesNameThePath) {
  EXPECT_THROW((void)from_json<LaserData>(json::parse(R"({"ranges":[70000]})")), JsonError);
  try {
    (void)from_json<LaserData>(json::parse(R"({"ranges":[1,-1]})"));
    FAIL();
  } catch (const JsonError& e) {
    EXPECT_EQ(std::string(e.what()), "player_laser_data_t.ranges[1]: -1 is out of range [0, 65535]");
  }
  EXPECT_THROW((void)from_json<PositionCommand>(json::parse(R"({"xspeed":"fast"})")), JsonError);
  EXPECT_THROW((void)from_json<PositionCommand>(json::parse(R"({"xspeed":1.5})")), JsonError);
  EXPECT_EQ(from_json<PositionCommand>(json::parse(R"({"xspeed":2.0})")).xspeed, 2);
}

TEST(JsonCodec, AHugeDoubleInAnIntegerFieldIsOutOfRangeNotUndefined) {
  // Found by the json_line fuzzer: 9e102 was cast to int64 before the range check.
  try {
    (void)from_json<PositionCommand>(json::parse(R"({"xspeed":9e102})"));
    FAIL();
  } catch (const JsonError& e) {
    EXPECT_NE(std::string(e.what()).find("is out of range"), std::string::npos) << e.what();
  }
  EXPECT_THROW((void)from_json<PositionCommand>(json::parse(R"({"xspeed":-1e300})")), JsonError);
  EXPECT_THROW((void)from_json<LaserData>(json::parse(R"({"ranges":[1e19]})")), JsonError);
  EXPECT_EQ(from_json<PositionCommand>(json::parse(R"({"xspeed":-3.0})")).xspeed, -3);
}

TEST(JsonCodec, TooManyElementsIsAnError) {
  json ranges = json::array();
  for (int i = 0; i < 402; ++i) ranges.push_back(i);
  EXPECT_THROW((void)from_json<LaserData>(json{{"ranges", ranges}}), JsonError);
}

TEST(JsonCodec, TextFieldsRoundTripEveryByte) {
  DeviceAccessReply reply;
  reply.driver_name = std::string_view("caf\xE9", 4);
  const json j = to_json(reply);
  EXPECT_EQ(j["driver_name"], "caf\u00e9");
  EXPECT_EQ(from_json<DeviceAccessReply>(j), reply);
  EXPECT_THROW((void)from_json<DeviceAccessReply>(json{{"driver_name", "\u20ac"}}), JsonError);
  EXPECT_THROW((void)from_json<DeviceAccessReply>(json{{"driver_name", std::string(65, 'x')}}), JsonError);
  // A full field has no NUL, exactly like one decoded from the wire.
  EXPECT_EQ(from_json<DeviceAccessReply>(json{{"driver_name", std::string(64, 'x')}}).driver_name.view(),
            std::string(64, 'x'));
}

TEST(JsonCodec, NestedStructsAndTwoDimensionalArrays) {
  SonarGeom geom;
  geom.subtype = 1;
  geom.pose_count = 2;
  geom.poses[0] = {115, 130, 90};
  geom.poses[1] = {155, -115, -50};
  const json j = to_json(geom);
  EXPECT_EQ(j["poses"], json::parse("[[115,130,90],[155,-115,-50]]"));
  EXPECT_EQ(from_json<SonarGeom>(j), geom);
}

TEST(JsonCodec, Int64FieldsKeepFullPrecision) {
  LocalizeHypothesis h;
  h.cov[0][1] = -9007199254740993;  // not representable as a double
  EXPECT_EQ(from_json<LocalizeHypothesis>(to_json(h)), h);
}

}  // namespace json_codec_test
}  // namespace playerkit::protocol
