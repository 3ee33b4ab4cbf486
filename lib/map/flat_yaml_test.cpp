#include "map/flat_yaml.hpp"

#include "map/map_file_error.hpp"

#include <gtest/gtest.h>

#include <string>

namespace playerkit::map {
namespace flat_yaml_test {

// The message of the MapFileError that parsing `text` throws.
std::string error_of(const std::string& text) {
  try {
    parse_flat_yaml(text, "m.yaml");
  } catch (const MapFileError& error) {
    return error.what();
  }
  return "no error";
}

TEST(FlatYaml, ReadsScalarsListsAndPositions) {
  const FlatYaml yaml = parse_flat_yaml(
      "# a map\n"
      "---\n"
      "image: my map.pgm   # trailing comment\n"
      "resolution: 0.050000\n"
      "origin: [-10.0,  2.5 , 0.0]\r\n"
      "\n"
      "empty:\n"
      "tag: \"a # not a comment\"\n"
      "single: 'it''s'\n"
      "escaped: \"q\\\"\\\\\"\n"
      "none: []\n",
      "m.yaml");
  ASSERT_EQ(yaml.size(), 8u);
  EXPECT_EQ(yaml.at("image").scalar.text, "my map.pgm");
  EXPECT_FALSE(yaml.at("image").scalar.quoted);
  EXPECT_EQ(yaml.at("image").line, 3);
  EXPECT_EQ(yaml.at("image").column, 8);
  EXPECT_EQ(yaml.at("resolution").scalar.text, "0.050000");

  const YamlValue& origin = yaml.at("origin");
  ASSERT_TRUE(origin.is_list);
  ASSERT_EQ(origin.items.size(), 3u);
  EXPECT_EQ(origin.items[0].text, "-10.0");
  EXPECT_EQ(origin.items[1].text, "2.5");
  EXPECT_EQ(origin.items[2].text, "0.0");
  EXPECT_EQ(origin.items[1].line, 5);
  EXPECT_EQ(origin.items[1].column, 18);

  EXPECT_FALSE(yaml.at("empty").is_list);
  EXPECT_EQ(yaml.at("empty").scalar.text, "");
  EXPECT_EQ(yaml.at("tag").scalar.text, "a # not a comment");
  EXPECT_TRUE(yaml.at("tag").scalar.quoted);
  EXPECT_EQ(yaml.at("single").scalar.text, "it's");
  EXPECT_EQ(yaml.at("escaped").scalar.text, "q\"\\");
  EXPECT_TRUE(yaml.at("none").is_list);
  EXPECT_TRUE(yaml.at("none").items.empty());
}

TEST(FlatYaml, EmptyTextHasNoKeys) {
  EXPECT_TRUE(parse_flat_yaml("", "m.yaml").empty());
  EXPECT_TRUE(parse_flat_yaml("# only a comment\n\n", "m.yaml").empty());
}

TEST(FlatYaml, ErrorsCarryLineAndColumn) {
  EXPECT_EQ(error_of("a: 1\nimage map.pgm\n"), "m.yaml:2:7: expected ':' after key 'image'");
  EXPECT_EQ(error_of("a:1\n"), "m.yaml:1:3: expected a space after ':'");
  EXPECT_EQ(error_of("a: 1\na: 2\n"), "m.yaml:2:1: duplicate key 'a'");
  EXPECT_EQ(error_of("a:\n  b: 1\n"),
            "m.yaml:2:3: indented line: nested values are not supported in a map file");
  EXPECT_EQ(error_of("list:\n- 1\n"),
            "m.yaml:2:1: expected a plain key (quoted keys, lists and mappings are not supported)");
  EXPECT_EQ(error_of("o: [1, 2\n"), "m.yaml:1:4: unterminated '['");
  EXPECT_EQ(error_of("o: [1, , 2]\n"), "m.yaml:1:8: empty list item");
  EXPECT_EQ(error_of("o: [1, [2]]\n"), "m.yaml:1:8: nested lists and mappings are not supported");
  EXPECT_EQ(error_of("o: [1 2] x\n"), "m.yaml:1:10: unexpected text after the value");
  EXPECT_EQ(error_of("o: {a: 1}\n"), "m.yaml:1:4: flow mappings ({...}) are not supported");
  EXPECT_EQ(error_of("\n\nimage: \"map.pgm\n"), "m.yaml:3:8: unterminated quoted string");
  EXPECT_EQ(error_of("image: \"map\" x\n"), "m.yaml:1:14: unexpected text after the value");
  EXPECT_EQ(error_of("s: \"\\q\"\n"), "m.yaml:1:5: unsupported escape '\\q'");
}

TEST(FlatYaml, ErrorExposesLineAndColumn) {
  try {
    parse_flat_yaml("ok: 1\n\n   bad: 2\n", "dir/m.yaml");
    FAIL() << "no error";
  } catch (const MapFileError& error) {
    EXPECT_EQ(error.line(), 3);
    EXPECT_EQ(error.column(), 4);
    EXPECT_EQ(std::string(error.what()).rfind("dir/m.yaml:3:4: ", 0), 0u) << error.what();
  }
}

}  // namespace flat_yaml_test
}  // namespace playerkit::map
