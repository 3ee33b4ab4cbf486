#include "outgoing_message.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "protocol/binary_codec.hpp"
#include "protocol/interfaces.hpp"
#include "protocol/messages/all.hpp"
#include "usage_error.hpp"

namespace playerkit::player_send {
namespace outgoing_message_test {

using protocol::MessageType;

protocol::Message build(std::vector<std::string> words) { return message_from_arguments(words); }

std::string error_of(std::vector<std::string> words) {
  try {
    message_from_arguments(words);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(OutgoingMessage, ACommandCarriesTheInterfacesCommandStruct) {
  const auto message = build({"position:1", "cmd", "xspeed=200", "yawspeed=10"});
  EXPECT_EQ(message.type(), MessageType::kCommand);
  EXPECT_EQ(message.device(), (protocol::DeviceAddress{protocol::kPositionCode, 1}));
  protocol::PositionCommand expected;
  expected.xspeed = 200;
  expected.yawspeed = 10;
  EXPECT_EQ(message.payload, protocol::encode(expected));
  EXPECT_EQ(message.header.size, message.payload.size());
}

TEST(OutgoingMessage, ACommandWithoutFieldsIsAllZeros) {
  EXPECT_EQ(build({"position", "cmd"}).payload, protocol::encode(protocol::PositionCommand{}));
}

TEST(OutgoingMessage, ARequestByNameGetsItsSubtypeFromTheCatalog) {
  const auto message = build({"mcom:0", "req", "pop", "channel=news"});
  EXPECT_EQ(message.type(), MessageType::kRequest);
  protocol::McomConfig expected;
  expected.command = protocol::kMcomPopReq;
  expected.channel = "news";
  EXPECT_EQ(message.payload, protocol::encode(expected));
}

TEST(OutgoingMessage, NestedFieldsReachNestedStructs) {
  const auto message = build({"mcom:0", "req", "push", "channel=news", "data.data=hello", "data.full=1"});
  protocol::McomConfig expected;
  expected.command = protocol::kMcomPushReq;
  expected.channel = "news";
  expected.data.full = 1;
  expected.data.data = "hello";
  EXPECT_EQ(message.payload, protocol::encode(expected));
}

TEST(OutgoingMessage, AQueryIsOnlyItsSubtype) {
  EXPECT_EQ(build({"position:0", "req", "get-geom"}).payload,
            (std::vector<std::uint8_t>{protocol::kPositionGetGeomReq}));
}

TEST(OutgoingMessage, ThePlayerDeviceHasTwoByteSubtypes) {
  const auto devlist = build({"player", "req", "devlist"});
  EXPECT_EQ(devlist.device(), (protocol::DeviceAddress{protocol::kPlayerCode, 0}));
  EXPECT_EQ(devlist.payload, (std::vector<std::uint8_t>{0, 1}));
  const auto info = build({"player", "req", "driverinfo", "id.code=26", "id.port=6665"});
  protocol::DriverInfo expected;
  expected.subtype = protocol::kPlayerDriverinfoReq;
  expected.id.code = 26;
  expected.id.port = 6665;
  EXPECT_EQ(info.payload, protocol::encode(expected));
}

TEST(OutgoingMessage, ListFieldsByElementOrWhole) {
  const auto by_element = build({"position:0", "req", "set-odom", "x=1000", "theta=90"});
  protocol::PositionSetOdomRequest expected;
  expected.subtype = protocol::kPositionSetOdomReq;
  expected.x = 1000;
  expected.theta = 90;
  EXPECT_EQ(by_element.payload, protocol::encode(expected));
  const auto comms = build({"comms:0", "cmd", "msg=[104,105]"});
  EXPECT_EQ(comms.payload, (std::vector<std::uint8_t>{104, 105}));
}

TEST(OutgoingMessage, AnUnknownInterfaceSuggestsTheNearestName) {
  const auto message = error_of({"lazer:0", "req", "get-geom"});
  EXPECT_CONTAINS(message, "unknown interface 'lazer'");
  EXPECT_CONTAINS(message, "did you mean laser?");
  EXPECT_CONTAINS(error_of({"position:x", "cmd"}), "index after ':' must be a number");
}

TEST(OutgoingMessage, TheVerbMustBeCmdOrReq) {
  EXPECT_CONTAINS(error_of({"position:0"}), "expected 'cmd' or 'req' after position:0");
  EXPECT_CONTAINS(error_of({"position:0", "go"}), "got 'go'");
  EXPECT_CONTAINS(error_of({}), "missing DEVICE");
}

TEST(OutgoingMessage, AnInterfaceWithoutACommandSaysWhatItTakes) {
  const auto message = error_of({"laser:0", "cmd", "x=1"});
  EXPECT_CONTAINS(message, "laser takes no commands");
  EXPECT_CONTAINS(message, "get-geom, set-config, get-config, power");
  EXPECT_CONTAINS(error_of({"gps:0", "req", "x"}), "gps takes no requests");
}

TEST(OutgoingMessage, AnUnknownRequestListsTheKnownOnes) {
  const auto message = error_of({"position:0", "req", "get-geo"});
  EXPECT_CONTAINS(message, "position has no request 'get-geo' (did you mean get-geom?)");
  EXPECT_CONTAINS(message, "set-odom");
  EXPECT_CONTAINS(error_of({"position:0", "req"}), "req needs a request name");
}

TEST(OutgoingMessage, AnUnknownFieldListsTheStructsFields) {
  const auto message = error_of({"position:0", "cmd", "xsped=1"});
  EXPECT_CONTAINS(message, "unknown field 'xsped'");
  EXPECT_CONTAINS(message, "xspeed");
}

TEST(OutgoingMessage, ABadValueNamesTheFieldAndTheRange) {
  EXPECT_CONTAINS(error_of({"position:0", "cmd", "xspeed=fast"}), "xspeed");
  EXPECT_CONTAINS(error_of({"position:0", "cmd", "state=300"}), "300 is out of range [0, 255]");
  EXPECT_CONTAINS(error_of({"mcom:0", "req", "push", "channel=muchtoolong"}), "does not fit");
  EXPECT_CONTAINS(error_of({"position:0", "req", "get-geom", "x=1"}), "takes no fields");
}

TEST(OutgoingMessage, RequestNamesForMessages) {
  EXPECT_EQ(request_names(protocol::kMcomCode), "push, pop, read, clear, set-capacity");
  EXPECT_EQ(request_names(protocol::kGpsCode), "none");
}

}  // namespace outgoing_message_test
}  // namespace playerkit::player_send
