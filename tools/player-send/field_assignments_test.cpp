#include "field_assignments.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "usage_error.hpp"

namespace playerkit::player_send {
namespace field_assignments_test {

using nlohmann::json;

json parse(std::vector<std::string> words) { return parse_field_assignments(words); }

std::string error_of(std::vector<std::string> words) {
  try {
    parse_field_assignments(words);
  } catch (const UsageError& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(FieldAssignments, NumbersBecomeJsonNumbers) {
  EXPECT_EQ(parse({"xspeed=200", "yawspeed=-10"}), json::parse(R"({"xspeed":200,"yawspeed":-10})"));
}

TEST(FieldAssignments, NoAssignmentsIsAnEmptyObject) { EXPECT_EQ(parse({}), json::object()); }

TEST(FieldAssignments, AWholeListOrOneElement) {
  EXPECT_EQ(parse({"pose=[1,2,3]"}), json::parse(R"({"pose":[1,2,3]})"));
  EXPECT_EQ(parse({"pose.2=5"}), json::parse(R"({"pose":[0,0,5]})"));
  EXPECT_EQ(parse({"pose.1=7", "pose.0=6"}), json::parse(R"({"pose":[6,7]})"));
}

TEST(FieldAssignments, NestedStructs) {
  EXPECT_EQ(parse({"id.code=26", "id.port=6665"}), json::parse(R"({"id":{"code":26,"port":6665}})"));
}

TEST(FieldAssignments, SkippedElementsTakeTheZeroOfTheirSiblings) {
  EXPECT_EQ(parse({"devices.1.code=5"}), json::parse(R"({"devices":[{},{"code":5}]})"));
  EXPECT_EQ(parse({"names.1=b"}), json::parse(R"({"names":["","b"]})"));
}

TEST(FieldAssignments, TextThatIsNotJsonIsAString) {
  EXPECT_EQ(parse({"channel=news"}), json::parse(R"({"channel":"news"})"));
  EXPECT_EQ(parse({"channel=hello world"}), json::parse(R"({"channel":"hello world"})"));
  EXPECT_EQ(parse({"channel="}), json::parse(R"({"channel":""})"));
  // Only the first '=' separates: the value may hold more.
  EXPECT_EQ(parse({"channel=a=b"}), json::parse(R"({"channel":"a=b"})"));
}

TEST(FieldAssignments, JsonQuotesForceText) {
  EXPECT_EQ(parse({"channel=\"42\""}), json::parse(R"({"channel":"42"})"));
  EXPECT_EQ(parse({"channel=42"}), json::parse(R"({"channel":42})"));
}

TEST(FieldAssignments, ParseValueKeepsJsonKinds) {
  EXPECT_EQ(parse_value("1.5"), json(1.5));
  EXPECT_EQ(parse_value("true"), json(true));
  EXPECT_EQ(parse_value("{\"a\":1}"), json::parse(R"({"a":1})"));
  EXPECT_EQ(parse_value("[1,"), json("[1,"));
}

TEST(FieldAssignments, AnArgumentWithoutEqualsIsRefused) {
  const auto message = error_of({"xspeed200"});
  EXPECT_NE(message.find("'xspeed200'"), std::string::npos) << message;
  EXPECT_NE(message.find("FIELD=VALUE"), std::string::npos) << message;
}

TEST(FieldAssignments, MalformedPathsAreRefusedByName) {
  EXPECT_NE(error_of({"=5"}).find("field name before '=' is missing"), std::string::npos);
  EXPECT_NE(error_of({"pose..1=2"}).find("'' is not a field name"), std::string::npos);
  EXPECT_NE(error_of({"x-y=1"}).find("'x-y' is not a field name"), std::string::npos);
  EXPECT_NE(error_of({"0=1"}).find("starts with a field name"), std::string::npos);
  EXPECT_NE(error_of({"pose.99999=1"}).find("element 99999 is beyond any payload"), std::string::npos);
  EXPECT_NE(error_of({"pose.123456789012345678901=1"}).find("beyond any payload"), std::string::npos);
}

TEST(FieldAssignments, AFieldGivenTwiceIsRefusedRatherThanOverwritten) {
  EXPECT_NE(error_of({"xspeed=1", "xspeed=2"}).find("xspeed is given more than once"), std::string::npos);
  EXPECT_NE(error_of({"pose=[1,2]", "pose.0=5"}).find("pose is given more than once"), std::string::npos);
  EXPECT_NE(error_of({"id.code=1", "id={}"}).find("id is given more than once"), std::string::npos);
}

TEST(FieldAssignments, AListCannotAlsoBeAStruct) {
  EXPECT_NE(error_of({"pose.0=1", "pose.x=2"}).find("pose is given as a list elsewhere"), std::string::npos);
  EXPECT_NE(error_of({"id.code=1", "id.0=2"}).find("id is given as a struct elsewhere"), std::string::npos);
}

}  // namespace field_assignments_test
}  // namespace playerkit::player_send
