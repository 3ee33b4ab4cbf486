#include "sim/worldfile/worldfile_syntax.hpp"

#include <gtest/gtest.h>

#include <string>

#include "support/scratch_directory.hpp"

namespace playerkit::sim::worldfile {
namespace worldfile_syntax_test {

WorldTree parse(const std::string& text) { return parse_world_text(text, "t.world"); }

// what() of the error the text raises, or "" when it parses.
std::string error_of(const std::string& text) {
  try {
    parse(text);
  } catch (const WorldFileError& error) {
    return error.what();
  }
  return "";
}

std::string texts(const Property& property) {
  std::string joined;
  for (const Value& value : property.values) joined += (joined.empty() ? "" : " ") + value.text;
  return joined;
}

TEST(WorldfileSyntax, WordsKeepTheirBracketsAndNumbersStayAsWritten) {
  const WorldTree tree = parse("spose[3] [ 0.115 -0.130 -90 ]\npolygon[0].point[1] [1 2]\nx +1.5\n");
  ASSERT_EQ(tree.world.properties.size(), 3u);
  EXPECT_EQ(tree.world.properties[0].name, "spose[3]");
  EXPECT_TRUE(tree.world.properties[0].tuple);
  EXPECT_EQ(texts(tree.world.properties[0]), "0.115 -0.130 -90");
  EXPECT_EQ(tree.world.properties[1].name, "polygon[0].point[1]");
  EXPECT_FALSE(tree.world.properties[2].tuple);
  EXPECT_EQ(texts(tree.world.properties[2]), "+1.5");
}

TEST(WorldfileSyntax, StringsAndNumbersMixInATupleAndKeepTheirLocations) {
  const WorldTree tree = parse("colors [ \"red\" 2 \"light blue\" ]\n");
  const Property& colors = tree.world.properties.at(0);
  ASSERT_EQ(colors.values.size(), 3u);
  EXPECT_TRUE(colors.values[0].is_string);
  EXPECT_EQ(colors.values[0].text, "red");
  EXPECT_FALSE(colors.values[1].is_string);
  EXPECT_EQ(colors.values[2].text, "light blue");
  EXPECT_EQ(to_string(colors.where), "t.world:1:1");
  EXPECT_EQ(to_string(colors.values[2].where), "t.world:1:18");
}

TEST(WorldfileSyntax, AnExponentIsNotPartOfANumber) {
  // 1e-3 lexes as the number 1 and the word e-3, which has no value.
  EXPECT_EQ(error_of("x 1e-3\n"),
            "t.world:1:4: \"e-3\" must be followed by a value on the same line (a property) or by '(' (an "
            "entity), found the end of the line");
}

TEST(WorldfileSyntax, AnEntityMayOpenAfterLineBreaksAndComments) {
  const WorldTree tree = parse("position # a robot\n\n# its body\n(\n  name \"r0\"\n)\n");
  ASSERT_EQ(tree.world.children.size(), 1u);
  const Entity& robot = tree.world.children[0];
  EXPECT_EQ(robot.type, "position");
  EXPECT_EQ(to_string(robot.where), "t.world:1:1");
  EXPECT_EQ(robot.find("name")->values.at(0).text, "r0");
  EXPECT_EQ(to_string(robot.find("name")->where), "t.world:5:3");
}

TEST(WorldfileSyntax, SeveralPropertiesMayShareALine) {
  const WorldTree tree = parse("box ( pose [1 2 3] size [0.3 0.3] color \"green\" )");
  const Entity& box = tree.world.children.at(0);
  EXPECT_EQ(texts(*box.find("pose")), "1 2 3");
  EXPECT_EQ(texts(*box.find("size")), "0.3 0.3");
  EXPECT_EQ(texts(*box.find("color")), "green");
}

TEST(WorldfileSyntax, APropertysValueMustStartOnItsNamesLine) {
  EXPECT_EQ(error_of("position\n(\n  pose\n  [1 2 3]\n)\n"),
            "t.world:3:3: a property's value must start on the same line as its name (\"pose\")");
}

TEST(WorldfileSyntax, StringsCloseOnTheirLine) {
  EXPECT_EQ(error_of("name \"abc\nx 1\n"),
            "t.world:1:6: unterminated string: a string must close on the line it starts");
  EXPECT_EQ(error_of("name \"abc"), "t.world:1:6: unterminated string: a string must close on the line it starts");
}

TEST(WorldfileSyntax, TuplesCloseOnOneLineAndHoldNoCommentsOrWords) {
  EXPECT_EQ(error_of("pose [1 2\n 3]\n"), "t.world:1:6: tuples must close on one line: this '[' has no ']' on its line");
  EXPECT_EQ(error_of("pose [1 2 # x\n"),
            "t.world:1:11: a tuple cannot hold a comment: close it with ']' on its line first");
  EXPECT_EQ(error_of("pose [1 two]\n"), "t.world:1:9: a tuple holds numbers and strings only, found the word \"two]\"");
  EXPECT_EQ(error_of("pose [1 [2]]\n"), "t.world:1:9: a tuple holds numbers and strings only, found '['");
}

TEST(WorldfileSyntax, CommasAndBracesAreNotPartOfTheLanguage) {
  EXPECT_EQ(error_of("pose [1, 2]\n"),
            "t.world:1:8: syntax error: unexpected character ',' (the values of a tuple are separated by spaces, "
            "not commas)");
  EXPECT_EQ(error_of("position {\n"),
            "t.world:1:10: syntax error: unexpected character '{' (entities are written with '(' and ')')");
  EXPECT_EQ(error_of("x 1\n\x1b[31m"), "t.world:2:1: syntax error: unexpected byte 0x1B");
}

TEST(WorldfileSyntax, ABareWordIsNoValue) {
  EXPECT_EQ(error_of("position ( name robot1 )"),
            "t.world:1:17: the value of \"name\" must be a number, a \"string\" or a [tuple], found the word "
            "\"robot1\"");
  // An entity without parentheses (pre-1.3 `player` lines).
  EXPECT_EQ(error_of("player\nposition ( )\n"),
            "t.world:1:1: \"player\" must be followed by a value on the same line (a property) or by '(' (an "
            "entity), found the end of the line");
}

TEST(WorldfileSyntax, AGluedTupleIsOneWord) {
  EXPECT_EQ(error_of("box ( pose[1 2 3] )"),
            "t.world:1:7: \"pose[1\" is one word: put a space between a property's name and its [tuple]");
}

TEST(WorldfileSyntax, StrayNumbersAndParentheses) {
  EXPECT_EQ(error_of("3\n"), "t.world:1:1: expected a property name or an entity type, found the number 3");
  EXPECT_EQ(error_of("box ( x 1 2 )"),
            "t.world:1:11: expected a property name or an entity type, found the number 2 (a property has one "
            "value: put several in a [tuple])");
  EXPECT_EQ(error_of("x 1\n)\n"), "t.world:2:1: misplaced ')': no entity is open here");
  EXPECT_EQ(error_of("position (\n  laser (\n)\n"), "t.world:1:10: missing ')': the entity opened here is not closed");
}

TEST(WorldfileSyntax, CrLfAndLfCrAreOneLineBreakEach) {
  EXPECT_EQ(error_of("a 1\r\n\n\r b\r\n"),
            "t.world:3:2: \"b\" must be followed by a value on the same line (a property) or by '(' (an entity), "
            "found the end of the line");
}

TEST(WorldfileSyntax, DefinesAreWrittenDefineNameBaseBody) {
  EXPECT_EQ(error_of("define a b c ( )"),
            "t.world:1:12: extra tokens in macro definition (a macro is written 'define NAME BASE ( ... )')");
  EXPECT_EQ(error_of("define a ( )"),
            "t.world:1:1: missing name in macro definition (a macro is written 'define NAME BASE ( ... )')");
  EXPECT_EQ(error_of("define a b 3"),
            "t.world:1:12: syntax error in macro definition: expected '(', found the number 3 (a macro is written "
            "'define NAME BASE ( ... )')");
  EXPECT_EQ(error_of("position ( define a b ( ) )"),
            "t.world:1:12: a define is allowed only at top level, outside every entity");
}

TEST(WorldfileMacros, BodiesApplyDeepestBaseFirstAndChildrenFollowTheSameOrder) {
  const WorldTree tree = parse(
      "define base_robot position ( x 1 y 1 z 1 sonar ( ) )\n"
      "define fancy base_robot ( y 2 z 2 laser ( ) )\n"
      "fancy ( z 3 ptz ( ) )\n");
  const Entity& robot = tree.world.children.at(0);
  EXPECT_EQ(robot.type, "position");
  EXPECT_EQ(robot.macros, (std::vector<std::string>{"fancy", "base_robot"}));
  EXPECT_EQ(robot.written_type(), "fancy");
  EXPECT_EQ(texts(*robot.find("x")), "1");
  EXPECT_EQ(texts(*robot.find("y")), "2");
  EXPECT_EQ(texts(*robot.find("z")), "3");
  ASSERT_EQ(robot.children.size(), 3u);
  EXPECT_EQ(robot.children[0].type, "sonar");
  EXPECT_EQ(robot.children[1].type, "laser");
  EXPECT_EQ(robot.children[2].type, "ptz");
  // The properties a macro gave keep the define's location.
  EXPECT_EQ(to_string(robot.find("x")->where), "t.world:1:30");
  EXPECT_EQ(to_string(robot.find("z")->where), "t.world:3:9");
  EXPECT_EQ(to_string(robot.children[0].where), "t.world:1:42");
}

TEST(WorldfileMacros, ALaterTupleReplacesTheWholeTuple) {
  const WorldTree tree = parse("define small position ( size [0.44 0.38] )\nsmall ( size [1] size [2 3 4] )\nsmall ( size [1] )");
  EXPECT_EQ(texts(*tree.world.children.at(0).find("size")), "2 3 4");
  EXPECT_EQ(texts(*tree.world.children.at(1).find("size")), "1");
}

TEST(WorldfileMacros, TheFirstDefinitionWinsWithAWarning) {
  const WorldTree tree = parse("define thing box ( x 1 )\ndefine thing puck ( x 2 )\nthing ( )\n");
  EXPECT_EQ(tree.world.children.at(0).type, "box");
  EXPECT_EQ(texts(*tree.world.children.at(0).find("x")), "1");
  ASSERT_EQ(tree.macros.size(), 1u);
  ASSERT_EQ(tree.warnings.size(), 1u);
  EXPECT_EQ(tree.warnings[0],
            "t.world:2:1: macro \"thing\" is defined again; the first definition, at t.world:1:1, is kept");
}

TEST(WorldfileMacros, AMacroIsLookedUpWhenInstantiated) {
  // Used before its define: the word stays a type (the loader reports it).
  const WorldTree early = parse("pioneer ( )\ndefine pioneer position ( )\n");
  EXPECT_EQ(early.world.children.at(0).type, "pioneer");
  // A macro body may use a macro defined after it, before the instance.
  const WorldTree late = parse("define robot position ( eye ( ) )\ndefine eye laser ( )\nrobot ( )\n");
  EXPECT_EQ(late.world.children.at(0).children.at(0).type, "laser");
}

TEST(WorldfileMacros, SelfReferenceIsAnError) {
  EXPECT_EQ(error_of("define a b ( )\ndefine b a ( )\na ( )\n"),
            "t.world:3:1: macro \"a\" is defined in terms of itself (its definition is at t.world:1:1)");
  EXPECT_EQ(error_of("define a position ( a ( ) )\na ( )\n"),
            "t.world:1:21: macro \"a\" contains an entity of its own type (its definition is at t.world:1:1)");
}

TEST(WorldfileMacros, DoublingMacrosAreCapped) {
  std::string text = "define m0 box ( x 1 y 1 )\n";
  for (int level = 1; level <= 24; ++level) {
    const std::string below = "m" + std::to_string(level - 1);
    text += "define m" + std::to_string(level) + " box ( " + below + " ( ) " + below + " ( ) )\n";
  }
  text += "m24 ( )\n";
  EXPECT_NE(error_of(text).find("more than 1000000 entities and properties once macros are expanded"),
            std::string::npos);
}

TEST(WorldfileSyntax, DeepNestingIsCapped) {
  std::string text;
  for (int i = 0; i < 40; ++i) text += "box ( ";
  EXPECT_EQ(error_of(text), "t.world:1:197: entities nested more than 32 deep");
}

namespace fs = std::filesystem;

TEST(WorldfileIncludes, IncludedTokensSpliceInAndKeepTheirOwnLines) {
  testing::ScratchDirectory scratch("worldfile_syntax_test");
  fs::create_directory(scratch.file("inc"));
  scratch.write("inc/robots.inc", "# robots\n\ndefine robot position ( size [0.4 0.4] )\ninclude \"inc/more.inc\"\n");
  // Resolved against the top-level file's directory, even from inc/robots.inc.
  scratch.write("inc/more.inc", "define eye laser ( )\n");
  const fs::path world = scratch.write("main.world", "x 1\ninclude \"inc/robots.inc\" # rest ignored ,;\nrobot ( eye ( ) )\n");
  const WorldTree tree = read_world_tree(world);
  EXPECT_EQ(tree.files.size(), 3u);
  const Entity& robot = tree.world.children.at(0);
  EXPECT_EQ(robot.type, "position");
  EXPECT_EQ(robot.children.at(0).type, "laser");
  EXPECT_EQ(to_string(robot.where), world.string() + ":3:1");
  EXPECT_EQ(to_string(robot.find("size")->where), (scratch.file("inc") / "robots.inc").string() + ":3:25");
}

TEST(WorldfileIncludes, ErrorsInAndAfterAnIncludeHaveTheirTrueLines) {
  testing::ScratchDirectory scratch("worldfile_syntax_test");
  scratch.write("bad.inc", "\n\nx [1 2\n");
  const fs::path bad = scratch.write("bad.world", "a 1\ninclude \"bad.inc\"\n");
  try {
    read_world_tree(bad);
    FAIL() << "no error";
  } catch (const WorldFileError& error) {
    EXPECT_EQ(error.what(), scratch.file("bad.inc").string() +
                                ":3:3: tuples must close on one line: this '[' has no ']' on its line");
  }
  scratch.write("good.inc", "\n\n\n\ndefine r position ( )\n");
  const fs::path after = scratch.write("after.world", "include \"good.inc\"\nr ( )\nr ( x\n");
  try {
    read_world_tree(after);
    FAIL() << "no error";
  } catch (const WorldFileError& error) {
    // Stage would say line 7 (it counts the included file's lines too).
    EXPECT_EQ(error.what(), after.string() +
                                ":3:5: \"x\" must be followed by a value on the same line (a property) or by '(' (an "
                                "entity), found the end of the line");
  }
}

TEST(WorldfileIncludes, CyclesMissingFilesAndMalformedStatementsAreErrors) {
  testing::ScratchDirectory scratch("worldfile_syntax_test");
  scratch.write("a.inc", "include \"b.inc\"\n");
  scratch.write("b.inc", "\ninclude \"./a.inc\"\n");
  const fs::path cycle = scratch.write("cycle.world", "include \"a.inc\"\n");
  try {
    read_world_tree(cycle);
    FAIL() << "no error";
  } catch (const WorldFileError& error) {
    EXPECT_EQ(error.what(), scratch.file("b.inc").string() + ":2:9: include cycle: cycle.world -> a.inc -> b.inc -> a.inc");
  }
  const fs::path missing = scratch.write("missing.world", "\n  include \"nowhere.inc\"\n");
  try {
    read_world_tree(missing);
    FAIL() << "no error";
  } catch (const WorldFileError& error) {
    EXPECT_EQ(error.what(), missing.string() + ":2:11: cannot read include file \"nowhere.inc\": no such file (looked for " +
                                scratch.file("nowhere.inc").string() + ")");
  }
  EXPECT_EQ(error_of("include\n"),
            "t.world:1:8: incomplete include statement: 'include' must be followed by a space and a file name in "
            "quotes on the same line");
  EXPECT_EQ(error_of("include x\n"),
            "t.world:1:9: incomplete include statement: 'include' must be followed by a space and a file name in "
            "quotes on the same line");
}

TEST(WorldfileIncludes, SizeAndCountAreCapped) {
  testing::ScratchDirectory scratch("worldfile_syntax_test");
  const fs::path big = scratch.write("big.world", std::string((1u << 20) + 1, '\n'));
  try {
    read_world_tree(big);
    FAIL() << "no error";
  } catch (const WorldFileError& error) {
    EXPECT_EQ(error.what(), big.string() +
                                ": cannot read the world file: too large: a world file with its includes may have "
                                "1048576 bytes at most");
  }
  scratch.write("one.inc", "x 1\n");
  std::string many;
  for (int i = 0; i < 257; ++i) many += "include \"one.inc\"\n";
  const fs::path repeated = scratch.write("many.world", many);
  try {
    read_world_tree(repeated);
    FAIL() << "no error";
  } catch (const WorldFileError& error) {
    EXPECT_EQ(error.what(), repeated.string() + ":257:9: include file \"one.inc\": more than 256 includes in one world");
  }
  const fs::path directory = scratch.write("dir.world", "include \"inc\"\n");
  fs::create_directory(scratch.file("inc"));
  try {
    read_world_tree(directory);
    FAIL() << "no error";
  } catch (const WorldFileError& error) {
    EXPECT_NE(std::string(error.what()).find("it is a directory, not a file"), std::string::npos) << error.what();
  }
}

}  // namespace worldfile_syntax_test
}  // namespace playerkit::sim::worldfile
