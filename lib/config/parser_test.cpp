// The grammar of server-behaviour.md §9.2: sections, properties, tuples,
// macros and the global unit settings.

#include "config/parser.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <string>
#include <vector>

#include "config/test_support.hpp"

namespace playerkit::config {
namespace parser_test {

using testing::data_path;
using testing::error_of;

ParsedConfig parse(std::string_view text) { return parse_text(text, "t.cfg"); }

std::string error_for(std::string_view text) {
  return error_of([&] { (void)parse(text); });
}

const Property& property_of(const ParsedSection& section, const std::string& name) {
  for (const Property& property : section.properties) {
    if (property.name == name) return property;
  }
  throw std::runtime_error("no property " + name + " in " + section.type);
}

std::vector<std::string> texts_of(const Property& property) {
  std::vector<std::string> texts;
  for (const Value& value : property.values) texts.push_back(value.text);
  return texts;
}

std::vector<std::string> names_of(const ParsedSection& section) {
  std::vector<std::string> names;
  for (const Property& property : section.properties) names.push_back(property.name);
  return names;
}

TEST(Parser, EmptyFileHasNoSectionsAndDefaultUnits) {
  const ParsedConfig config = parse("\n# nothing\n\n");
  EXPECT_TRUE(config.sections.empty());
  EXPECT_EQ(config.units.length, 1.0);
  EXPECT_DOUBLE_EQ(config.units.angle, std::numbers::pi / 180.0);
}

TEST(Parser, SectionsWithPropertiesOnOneLine) {
  const ParsedConfig config = parse(
      "position:0 ( driver \"p2os_position\" port \"/dev/ttyS0\" )"
      " sonar:0 ( driver \"p2os_sonar\" )\n");
  ASSERT_EQ(config.sections.size(), 2u);
  const ParsedSection& position = config.sections[0];
  EXPECT_EQ(position.type, "position:0");
  EXPECT_EQ(position.parent, -1);
  EXPECT_EQ(position.where, (SourceLocation{"t.cfg", 1, 1}));
  EXPECT_EQ(names_of(position), (std::vector<std::string>{"driver", "port"}));
  const Property& port = property_of(position, "port");
  EXPECT_FALSE(port.is_tuple);
  ASSERT_EQ(port.values.size(), 1u);
  EXPECT_EQ(port.values[0], (Value{"/dev/ttyS0", true, SourceLocation{"t.cfg", 1, 42}}));
  EXPECT_EQ(port.where, (SourceLocation{"t.cfg", 1, 37}));
  EXPECT_EQ(config.sections[1].type, "sonar:0");
  EXPECT_EQ(config.sections[1].where, (SourceLocation{"t.cfg", 1, 57}));
}

TEST(Parser, OpeningParenMayFollowOnLaterLinesAndAfterComments) {
  const ParsedConfig config = parse("laser:0   # the front laser\n\n(\n  port \"/dev/ttyS2\"\n)\n");
  ASSERT_EQ(config.sections.size(), 1u);
  EXPECT_EQ(config.sections[0].type, "laser:0");
  EXPECT_EQ(texts_of(property_of(config.sections[0], "port")),
            (std::vector<std::string>{"/dev/ttyS2"}));
}

TEST(Parser, CrLfLineEndings) {
  const ParsedConfig config = parse("laser:0\r\n(\r\n  port \"/dev/ttyS2\"\r\n)\r\n");
  ASSERT_EQ(config.sections.size(), 1u);
  const Property& port = property_of(config.sections[0], "port");
  EXPECT_EQ(texts_of(port), (std::vector<std::string>{"/dev/ttyS2"}));
  EXPECT_EQ(port.where, (SourceLocation{"t.cfg", 3, 3}));
}

TEST(Parser, EmptySectionsAndGluedParens) {
  const ParsedConfig config = parse("laser:0() null:0 ( )");
  ASSERT_EQ(config.sections.size(), 2u);
  EXPECT_TRUE(config.sections[0].properties.empty());
  EXPECT_EQ(config.sections[1].type, "null:0");
}

TEST(Parser, NumbersStringsAndTuples) {
  const ParsedConfig config = parse(
      "laser:0 (\n"
      "  rate 38400\n"
      "  pose [ 0.1 -0.2 +90 ]\n"
      "  devices [\"position:0\" \"laser:0\"]\n"
      "  mixed [ 1 \"two\" ]\n"
      "  empty [ ]\n"
      ")\n");
  const ParsedSection& laser = config.sections.at(0);
  const Property& rate = property_of(laser, "rate");
  EXPECT_FALSE(rate.is_tuple);
  EXPECT_EQ(rate.values.at(0), (Value{"38400", false, SourceLocation{"t.cfg", 2, 8}}));
  const Property& pose = property_of(laser, "pose");
  EXPECT_TRUE(pose.is_tuple);
  EXPECT_EQ(texts_of(pose), (std::vector<std::string>{"0.1", "-0.2", "+90"}));
  EXPECT_EQ(pose.values[2].where, (SourceLocation{"t.cfg", 3, 19}));
  const Property& devices = property_of(laser, "devices");
  EXPECT_EQ(texts_of(devices), (std::vector<std::string>{"position:0", "laser:0"}));
  EXPECT_TRUE(devices.values[0].is_string);
  const Property& mixed = property_of(laser, "mixed");
  EXPECT_FALSE(mixed.values[0].is_string);
  EXPECT_TRUE(mixed.values[1].is_string);
  EXPECT_TRUE(property_of(laser, "empty").is_tuple);
  EXPECT_TRUE(property_of(laser, "empty").values.empty());
}

TEST(Parser, NestedSectionsRecordTheirParent) {
  const ParsedConfig config = parse(
      "robot:6666:bob (\n"
      "  position:0 ( driver \"p2os_position\" )\n"
      "  laser:0 ( inner:0 () )\n"
      ")\n"
      "robot:7000 ()\n");
  ASSERT_EQ(config.sections.size(), 5u);
  const std::vector<std::pair<std::string, int>> expected = {{"robot:6666:bob", -1},
                                                             {"position:0", 0},
                                                             {"laser:0", 0},
                                                             {"inner:0", 2},
                                                             {"robot:7000", -1}};
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(config.sections[i].type, expected[i].first);
    EXPECT_EQ(config.sections[i].parent, expected[i].second) << expected[i].first;
  }
}

TEST(Parser, PropertyGivenTwiceKeepsItsPlaceAndTakesTheLaterValue) {
  const ParsedConfig config = parse(
      "laser:0 ( port \"/dev/ttyS1\" rate 9600\n"
      "  pose [ 1 2 3 ]\n"
      "  port \"/dev/ttyS2\"\n"
      "  pose [ 4 ]\n"
      ")\n");
  const ParsedSection& laser = config.sections.at(0);
  EXPECT_EQ(names_of(laser), (std::vector<std::string>{"port", "rate", "pose"}));
  const Property& port = property_of(laser, "port");
  EXPECT_EQ(texts_of(port), (std::vector<std::string>{"/dev/ttyS2"}));
  EXPECT_EQ(port.where, (SourceLocation{"t.cfg", 3, 3}));
  EXPECT_EQ(texts_of(property_of(laser, "pose")), (std::vector<std::string>{"4"}));
}

TEST(Parser, MacroInstanceHasTheBaseTypeAndTheMacroProperties) {
  const ParsedConfig config = parse(
      "define pioneer2 position (driver \"p2os_position\" port \"/dev/ttyS0\")\n"
      "pioneer2 ()\n");
  ASSERT_EQ(config.sections.size(), 1u);
  const ParsedSection& robot = config.sections[0];
  EXPECT_EQ(robot.type, "position");
  EXPECT_EQ(robot.where, (SourceLocation{"t.cfg", 2, 1}));
  EXPECT_EQ(texts_of(property_of(robot, "driver")), (std::vector<std::string>{"p2os_position"}));
  // A macro's properties keep the location of the define.
  EXPECT_EQ(property_of(robot, "port").where, (SourceLocation{"t.cfg", 1, 50}));
}

TEST(Parser, InstancePropertiesOverrideTheMacro) {
  const ParsedConfig config = parse(
      "define pioneer2 position:1 ( driver \"p2os_position\" port \"/dev/ttyS0\" )\n"
      "pioneer2 ( port \"/dev/ttyS3\" radio 1 )\n"
      "pioneer2 ( )\n");
  ASSERT_EQ(config.sections.size(), 2u);
  EXPECT_EQ(config.sections[0].type, "position:1");
  EXPECT_EQ(names_of(config.sections[0]), (std::vector<std::string>{"driver", "port", "radio"}));
  EXPECT_EQ(texts_of(property_of(config.sections[0], "port")),
            (std::vector<std::string>{"/dev/ttyS3"}));
  // The macro itself is unchanged by an instance.
  EXPECT_EQ(texts_of(property_of(config.sections[1], "port")),
            (std::vector<std::string>{"/dev/ttyS0"}));
}

TEST(Parser, MacroMayBuildOnAnotherMacro) {
  const ParsedConfig config = parse(
      "define base laser ( driver \"sicklms200\" rate 9600 )\n"
      "define fast base ( rate 38400 )\n"
      "fast ( port \"/dev/ttyS2\" )\n");
  ASSERT_EQ(config.sections.size(), 1u);
  EXPECT_EQ(config.sections[0].type, "laser");
  EXPECT_EQ(names_of(config.sections[0]), (std::vector<std::string>{"driver", "rate", "port"}));
  EXPECT_EQ(texts_of(property_of(config.sections[0], "rate")), (std::vector<std::string>{"38400"}));
}

TEST(Parser, MacroBodyMaySpanLinesAndHoldSubsections) {
  const ParsedConfig config = parse(
      "define bot robot:7000\n"
      "(\n"
      "  position:0 ( driver \"p2os_position\" )\n"
      ")\n"
      "bot ( laser:0 () )\n");
  ASSERT_EQ(config.sections.size(), 3u);
  EXPECT_EQ(config.sections[0].type, "robot:7000");
  EXPECT_EQ(config.sections[1].type, "position:0");
  EXPECT_EQ(config.sections[1].parent, 0);
  EXPECT_EQ(config.sections[2].type, "laser:0");
  EXPECT_EQ(config.sections[2].parent, 0);
}

TEST(Parser, UnusedMacroCreatesNoSection) {
  EXPECT_TRUE(parse("define pioneer2 position ( driver \"p2os_position\" )\n").sections.empty());
}

TEST(Parser, UnitSettings) {
  const ParsedConfig config = parse("unit_length \"cm\"\nunit_angle \"radians\"\n");
  EXPECT_DOUBLE_EQ(config.units.length, 0.01);
  EXPECT_EQ(config.units.angle, 1.0);
  EXPECT_DOUBLE_EQ(parse("unit_length \"mm\"").units.length, 0.001);
  EXPECT_EQ(parse("unit_length \"m\"").units.length, 1.0);
  EXPECT_DOUBLE_EQ(parse("unit_angle \"degrees\"").units.angle, std::numbers::pi / 180.0);
}

TEST(Parser, LaterUnitSettingWins) {
  EXPECT_DOUBLE_EQ(parse("unit_length \"cm\"\nlaser:0 ()\nunit_length \"mm\"\n").units.length,
                   0.001);
}

TEST(Parser, UnitSettingInsideASectionIsAnOrdinaryProperty) {
  const ParsedConfig config = parse("laser:0 ( unit_length \"mm\" )");
  EXPECT_EQ(config.units.length, 1.0);
  EXPECT_EQ(config.sections[0].properties.size(), 1u);
}

TEST(Parser, UnitSettingsOfAnIncludedFileApply) {
  const std::string text = "include \"" + data_path("units-cm.cfg") + "\"\nlaser:0 ()\n";
  EXPECT_DOUBLE_EQ(parse(text).units.length, 0.01);
}

TEST(ParserErrors, UnknownUnitsAreRejected) {
  EXPECT_EQ(error_for("unit_length \"inch\""),
            "t.cfg:1:13: unknown unit_length \"inch\" (expected \"m\", \"cm\" or \"mm\")");
  EXPECT_EQ(error_for("unit_length 1"),
            "t.cfg:1:13: unknown unit_length 1 (expected \"m\", \"cm\" or \"mm\")");
  EXPECT_EQ(error_for("\nunit_angle \"deg\""),
            "t.cfg:2:12: unknown unit_angle \"deg\" (expected \"degrees\" or \"radians\")");
  EXPECT_EQ(error_for("unit_angle [ \"radians\" ]"),
            "t.cfg:1:1: unit_angle takes a single value, not a tuple");
}

TEST(ParserErrors, OtherGlobalPropertiesAreRejected) {
  EXPECT_EQ(error_for("laser:0 ()\nport \"/dev/ttyS0\"\n"),
            "t.cfg:2:1: property 'port' is outside any section (only unit_length and unit_angle "
            "may be set at global level)");
  EXPECT_EQ(error_for("test 1"),
            "t.cfg:1:1: property 'test' is outside any section (only unit_length and unit_angle "
            "may be set at global level)");
}

TEST(ParserErrors, ValueMustBeOnTheNameLine) {
  EXPECT_EQ(error_for("laser:0 (\n  port\n  \"/dev/ttyS1\"\n)"),
            "t.cfg:2:3: missing value for 'port': a property's value must be on the same line as "
            "its name");
  EXPECT_EQ(error_for("laser:0 ( pose\n [ 1 2 3 ] )"),
            "t.cfg:1:11: missing value for 'pose': a property's value must be on the same line as "
            "its name");
}

TEST(ParserErrors, WordNeedsAValueOrParen) {
  EXPECT_EQ(error_for("laser:0\nport \"x\""),
            "t.cfg:1:8: syntax error: expected a value or '(' after 'laser:0', found newline");
  EXPECT_EQ(error_for("laser:0 ( driver )"),
            "t.cfg:1:18: syntax error: expected a value or '(' after 'driver', found ')'");
  EXPECT_EQ(error_for("laser:0 ( driver sicklms200 )"),
            "t.cfg:1:18: syntax error: expected a value or '(' after 'driver', found word "
            "'sicklms200'");
  EXPECT_EQ(error_for("laser:0"),
            "t.cfg:1:8: syntax error: expected a value or '(' after 'laser:0', found end of file");
}

TEST(ParserErrors, StrayTokensWhereAnItemShouldStart) {
  EXPECT_EQ(error_for("6665"),
            "t.cfg:1:1: syntax error: expected a property or a section, found number '6665'");
  EXPECT_EQ(error_for("laser:0 ( \"x\" )"),
            "t.cfg:1:11: syntax error: expected a property or a section, found string \"x\"");
  EXPECT_EQ(error_for("( driver \"x\" )"),
            "t.cfg:1:1: syntax error: expected a property or a section, found '('");
  EXPECT_EQ(error_for("laser:0 ( [ 1 ] )"),
            "t.cfg:1:11: syntax error: expected a property or a section, found '['");
}

TEST(ParserErrors, GluedBracketMakesTheWordSwallowIt) {
  // "pose[0" is a word and takes the first 0 as its value; the second 0 is left over.
  EXPECT_EQ(error_for("laser:0 ( pose[0 0 0] )"),
            "t.cfg:1:20: syntax error: expected a property or a section, found number '0'");
}

TEST(ParserErrors, NumberWithALetterIsMalformed) {
  EXPECT_EQ(
      error_for("localize:0 ( map_scale 5e-2 )"),
      "t.cfg:1:24: malformed number '5e-2': a number may only contain digits, '.', '+' and '-'");
  EXPECT_EQ(
      error_for("laser:0 ( pose [ 10cm 0 0 ] )"),
      "t.cfg:1:18: malformed number '10cm': a number may only contain digits, '.', '+' and '-'");
  // A number followed by a word after a space is two items, and the word is the problem.
  EXPECT_EQ(error_for("laser:0 ( rate 9600 baud )"),
            "t.cfg:1:26: syntax error: expected a value or '(' after 'baud', found ')'");
}

TEST(ParserErrors, UnbalancedParensPointAtTheUnmatchedOne) {
  EXPECT_EQ(error_for("laser:0 (\n  port \"x\"\n"),
            "t.cfg:1:9: unmatched '(': section 'laser:0' is not closed with ')'");
  EXPECT_EQ(error_for("robot:7000 (\n  laser:0 ( port \"x\" )\n"),
            "t.cfg:1:12: unmatched '(': section 'robot:7000' is not closed with ')'");
  EXPECT_EQ(error_for("laser:0 ( port \"x\" ) )"), "t.cfg:1:22: unmatched ')'");
  EXPECT_EQ(error_for(")"), "t.cfg:1:1: unmatched ')'");
}

TEST(ParserErrors, TuplesEndOnTheirLine) {
  EXPECT_EQ(error_for("laser:0 ( pose [ 0 0\n 0 ] )"),
            "t.cfg:1:16: unmatched '[': the tuple of 'pose' must end with ']' on the same line");
  // A comment hides the closing bracket.
  EXPECT_EQ(error_for("laser:0 ( pose [ 0 0 # x ]\n)"),
            "t.cfg:1:16: unmatched '[': the tuple of 'pose' must end with ']' on the same line");
  EXPECT_EQ(error_for("laser:0 ( pose [ 0 0"),
            "t.cfg:1:16: unmatched '[': the tuple of 'pose' must end with ']' on the same line");
}

TEST(ParserErrors, TuplesHoldOnlyNumbersAndStrings) {
  EXPECT_EQ(error_for("laser:0 ( pose [ 0 zero 0 ] )"),
            "t.cfg:1:20: syntax error: expected a number or a string in the tuple of 'pose', found "
            "word 'zero'");
  EXPECT_EQ(error_for("laser:0 ( pose [ 0 [ 1 ] ] )"),
            "t.cfg:1:20: syntax error: expected a number or a string in the tuple of 'pose', found "
            "'['");
  EXPECT_EQ(error_for("laser:0 ( pose [ 0 ) ] )"),
            "t.cfg:1:20: syntax error: expected a number or a string in the tuple of 'pose', found "
            "')'");
}

TEST(ParserErrors, DefineSyntax) {
  EXPECT_EQ(error_for("define ( )"),
            "t.cfg:1:8: syntax error: expected a macro name after 'define', found '('");
  EXPECT_EQ(
      error_for("define pioneer2 ( driver \"p2os_position\" )"),
      "t.cfg:1:17: syntax error: expected the type of macro 'pioneer2' after its name, found '('");
  EXPECT_EQ(error_for("define pioneer2 position driver \"p2os_position\""),
            "t.cfg:1:26: syntax error: expected '(' after 'define pioneer2 position', found word "
            "'driver'");
  EXPECT_EQ(error_for("define pioneer2 position ( driver \"p2os_position\"\n"),
            "t.cfg:1:26: unmatched '(': macro 'pioneer2' is not closed with ')'");
}

TEST(ParserErrors, DefineOnlyAtGlobalLevelAndOnce) {
  EXPECT_EQ(error_for("position:0 (\n  define fast position ( )\n)"),
            "t.cfg:2:3: 'define' is only allowed at global level");
  EXPECT_EQ(error_for("define a laser ( )\n\ndefine a sonar ( )"),
            "t.cfg:3:8: macro 'a' is already defined at t.cfg:1:8");
}

TEST(ParserErrors, LexerErrorsComeThrough) {
  EXPECT_EQ(error_for("laser:0 ( port \"x )"),
            "t.cfg:1:16: unterminated string: missing closing '\"' on this line");
}

}  // namespace parser_test
}  // namespace playerkit::config
