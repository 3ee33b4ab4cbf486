#include "json_line.hpp"

#include <gtest/gtest.h>

#include <string>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/message_json.hpp"
#include "protocol/messages/all.hpp"
#include "usage_error.hpp"

namespace playerkit::player_send {
namespace json_line_test {

using protocol::MessageType;

std::string error_of(std::string_view line) {
  try {
    message_from_line(line);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(JsonLine, TheShortFormIsACommand) {
  const auto message = message_from_line(R"({"device":"position:2","data":{"xspeed":200}})");
  EXPECT_EQ(message.type(), MessageType::kCommand);
  EXPECT_EQ(message.device(), (protocol::DeviceAddress{protocol::kPositionCode, 2}));
  protocol::PositionCommand expected;
  expected.xspeed = 200;
  EXPECT_EQ(message.payload, protocol::encode(expected));
}

TEST(JsonLine, NamingARequestMakesTheLineARequest) {
  const auto message = message_from_line(R"({"device":"mcom:0","request":"pop","data":{"channel":"news"}})");
  EXPECT_EQ(message.type(), MessageType::kRequest);
  protocol::McomConfig expected;
  expected.command = protocol::kMcomPopReq;
  expected.channel = "news";
  EXPECT_EQ(message.payload, protocol::encode(expected));
}

TEST(JsonLine, MissingDataIsAllZeros) {
  EXPECT_EQ(message_from_line(R"({"device":"position"})").payload, protocol::encode(protocol::PositionCommand{}));
}

TEST(JsonLine, TheFullFormThatMessageToJsonPrintsRoundTrips) {
  protocol::PositionCommand command;
  command.xspeed = -150;
  command.yawspeed = 30;
  protocol::Message original;
  original.header = protocol::make_header(MessageType::kCommand, {protocol::kPositionCode, 3},
                                          protocol::Timestamp{1086000000, 250000}, {});
  original.payload = protocol::encode(command);
  const auto line = protocol::message_to_json(original).dump();
  const auto parsed = message_from_line(line);
  EXPECT_EQ(parsed.type(), MessageType::kCommand);
  EXPECT_EQ(parsed.device(), original.device());
  EXPECT_EQ(parsed.payload, original.payload);
}

TEST(JsonLine, AFullFormRequestKeepsItsName) {
  const auto parsed = message_from_line(
      R"({"type":"req","device":"position","index":0,"request":"set-odom","data":{"x":5,"y":6,"theta":7}})");
  protocol::PositionSetOdomRequest expected;
  expected.subtype = protocol::kPositionSetOdomReq;
  expected.x = 5;
  expected.y = 6;
  expected.theta = 7;
  EXPECT_EQ(parsed.payload, protocol::encode(expected));
}

TEST(JsonLine, RawBytesGoAsTheyAre) {
  EXPECT_EQ(message_from_line(R"({"device":"comms:0","data":{"raw":[1,2,3]}})").payload,
            (std::vector<std::uint8_t>{1, 2, 3}));
}

TEST(JsonLine, WhatIsNotAnObjectIsRefused) {
  EXPECT_CONTAINS(error_of("{\"device\":"), "not valid JSON");
  EXPECT_CONTAINS(error_of("[1,2]"), "expected a JSON object");
}

TEST(JsonLine, AMisspeltKeyIsAnErrorNotZeros) {
  EXPECT_CONTAINS(error_of(R"({"device":"position:0","dta":{"xspeed":1}})"), "unknown key 'dta'");
}

TEST(JsonLine, OnlyCommandsAndRequestsCanBeSent) {
  EXPECT_CONTAINS(error_of(R"({"type":"data","device":"position:0","data":{}})"), "\"type\":\"data\" cannot be sent");
  EXPECT_CONTAINS(error_of(R"({"type":"cmd","device":"mcom:0","request":"pop"})"), "names a \"request\"");
}

TEST(JsonLine, TheDeviceMustBeThereAndAgreeWithTheIndex) {
  EXPECT_CONTAINS(error_of(R"({"data":{}})"), "\"device\" is missing");
  EXPECT_CONTAINS(error_of(R"({"device":"position:1","index":2})"), "disagree");
  EXPECT_CONTAINS(error_of(R"({"device":"postion:0"})"), "did you mean position?");
  EXPECT_CONTAINS(error_of(R"({"device":"position","index":"zero"})"), "\"index\" must be a number");
  EXPECT_CONTAINS(error_of(R"({"device":"position","index":70000})"), "\"index\" must be a number");
}

TEST(JsonLine, BadFieldsAndRequestsAreNamed) {
  EXPECT_CONTAINS(error_of(R"({"device":"position:0","data":{"xsped":1}})"), "unknown field 'xsped'");
  EXPECT_CONTAINS(error_of(R"({"device":"position:0","request":"fly"})"), "has no request 'fly'");
  EXPECT_CONTAINS(error_of(R"({"device":"laser:0","data":{"x":1}})"), "laser has no cmd struct");
}

}  // namespace json_line_test
}  // namespace playerkit::player_send
