// Typed reads of a section's properties (server-behaviour.md §9.3).

#include "config/section.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <numbers>
#include <string>

#include "config/parser.hpp"
#include "config/test_support.hpp"

namespace playerkit::config {
namespace section_test {

using testing::data_path;

constexpr double kDegree = std::numbers::pi / 180.0;

// The first section of `text`, as ConfigFile builds it.
Section first_section(std::string_view text, const std::string& file = "/robots/pioneer.cfg") {
  ParsedConfig parsed = parse_text(text, file);
  return Section(std::move(parsed.sections.at(0)), parsed.units);
}

const Section kLaser = first_section(
    "laser:0 (\n"
    "  port \"/dev/ttyS1\"\n"
    "  rate 38400\n"
    "  delay \"12abc\"\n"
    "  scale 0.05\n"
    "  pose [ 10 -20 90 ]\n"
    "  names [ \"a\" \"b\" ]\n"
    "  empty [ ]\n"
    ")\n");

TEST(Section, TypeParentAndLocation) {
  EXPECT_EQ(kLaser.type(), "laser:0");
  EXPECT_EQ(kLaser.parent(), -1);
  EXPECT_EQ(kLaser.where(), (SourceLocation{"/robots/pioneer.cfg", 1, 1}));
}

TEST(Section, PropertyNamesInOrder) {
  EXPECT_EQ(kLaser.property_names(),
            (std::vector<std::string>{"port", "rate", "delay", "scale", "pose", "names", "empty"}));
  EXPECT_TRUE(kLaser.has("pose"));
  EXPECT_TRUE(kLaser.has("empty"));
  EXPECT_FALSE(kLaser.has("Pose"));
  ASSERT_NE(kLaser.property("rate"), nullptr);
  EXPECT_EQ(kLaser.property("rate")->where, (SourceLocation{"/robots/pioneer.cfg", 3, 3}));
  EXPECT_EQ(kLaser.property("nothing"), nullptr);
}

TEST(Section, ReadString) {
  EXPECT_EQ(kLaser.read_string("port", "/dev/ttyS0"), "/dev/ttyS1");
  EXPECT_EQ(kLaser.read_string("rate", ""), "38400");  // a number's text
  EXPECT_EQ(kLaser.read_string("names", ""), "a");     // a tuple's first element
  EXPECT_EQ(kLaser.read_string("missing", "fallback"), "fallback");
  EXPECT_EQ(kLaser.read_string("empty", "fallback"), "fallback");
}

TEST(Section, ReadIntUsesAtoi) {
  EXPECT_EQ(kLaser.read_int("rate", 9600), 38400);
  EXPECT_EQ(kLaser.read_int("delay", 0), 12);  // "12abc"
  EXPECT_EQ(kLaser.read_int("port", 5), 0);    // "/dev/ttyS1" has no digits up front
  EXPECT_EQ(kLaser.read_int("scale", 7), 0);   // "0.05"
  EXPECT_EQ(kLaser.read_int("pose", 0), 10);   // first element
  EXPECT_EQ(kLaser.read_int("missing", -1), -1);
}

TEST(Section, ReadFloatUsesAtof) {
  EXPECT_DOUBLE_EQ(kLaser.read_float("scale", 1.0), 0.05);
  EXPECT_DOUBLE_EQ(kLaser.read_float("delay", 0.0), 12.0);
  EXPECT_DOUBLE_EQ(kLaser.read_float("missing", 2.5), 2.5);
}

TEST(Section, ReadLengthConvertsToMetres) {
  EXPECT_DOUBLE_EQ(kLaser.read_length("scale", 1.0), 0.05);
  EXPECT_DOUBLE_EQ(first_section("unit_length \"cm\"\nlaser:0 ( r 25 )").read_length("r", 0), 0.25);
  EXPECT_DOUBLE_EQ(first_section("unit_length \"mm\"\nlaser:0 ( r 250 )").read_length("r", 0),
                   0.25);
}

TEST(Section, LengthFallbackIsNotConverted) {
  const Section section = first_section("unit_length \"mm\"\nlaser:0 ( )");
  EXPECT_EQ(section.read_length("radius", 0.2), 0.2);
  EXPECT_EQ(section.read_tuple_length("pose", 0, 0.3), 0.3);
}

TEST(Section, ReadAngleConvertsToRadians) {
  EXPECT_DOUBLE_EQ(kLaser.read_tuple_angle("pose", 2, 0), std::numbers::pi / 2);
  const Section radians = first_section("unit_angle \"radians\"\nptz:0 ( fov 1.5 )");
  EXPECT_DOUBLE_EQ(radians.read_angle("fov", 0), 1.5);
  EXPECT_EQ(radians.read_angle("missing", 90.0), 90.0);  // not converted
  EXPECT_EQ(kLaser.read_angle("missing", 10.0), 10.0);
}

TEST(Section, UnitsApplyWhereverTheyAreSet) {
  // unit_length is global: written after the section it still applies to it.
  const Section section = first_section("laser:0 ( r 5 )\nunit_length \"cm\"\n");
  EXPECT_DOUBLE_EQ(section.read_length("r", 0), 0.05);
  EXPECT_DOUBLE_EQ(section.units().length, 0.01);
}

TEST(Section, Tuples) {
  EXPECT_EQ(kLaser.tuple_size("pose"), 3u);
  EXPECT_EQ(kLaser.tuple_size("port"), 1u);
  EXPECT_EQ(kLaser.tuple_size("empty"), 0u);
  EXPECT_EQ(kLaser.tuple_size("missing"), 0u);
  EXPECT_EQ(kLaser.read_tuple_int("pose", 1, 0), -20);
  EXPECT_DOUBLE_EQ(kLaser.read_tuple_float("pose", 0, 0), 10.0);
  EXPECT_DOUBLE_EQ(kLaser.read_tuple_length("pose", 1, 0), -20.0);
  EXPECT_DOUBLE_EQ(kLaser.read_tuple_angle("pose", 0, 0), 10 * kDegree);
  EXPECT_EQ(kLaser.read_tuple_string("names", 1, ""), "b");
  EXPECT_EQ(kLaser.read_tuple_string("port", 0, ""), "/dev/ttyS1");  // a plain value is element 0
}

TEST(Section, MissingTupleElementGivesTheFallback) {
  EXPECT_EQ(kLaser.read_tuple_int("pose", 3, 99), 99);
  EXPECT_EQ(kLaser.read_tuple_string("port", 1, "none"), "none");
  EXPECT_EQ(kLaser.read_tuple_float("empty", 0, 1.5), 1.5);
  EXPECT_EQ(kLaser.read_tuple_float("missing", 0, 2.5), 2.5);
}

TEST(Section, RelativeFilenameIsResolvedAgainstTheFileDirectory) {
  const Section amcl =
      first_section("localize:0 ( map_file \"maps/cave.pnm\" )", "/home/me/robots/amcl.cfg");
  EXPECT_EQ(amcl.read_filename("map_file", ""), "/home/me/robots/maps/cave.pnm");
}

TEST(Section, AbsoluteAndHomeFilenamesAreKept) {
  EXPECT_EQ(first_section("x:0 ( f \"/srv/map.pgm\" )").read_filename("f", ""), "/srv/map.pgm");
  EXPECT_EQ(first_section("x:0 ( f \"~/map.pgm\" )").read_filename("f", ""), "~/map.pgm");
}

TEST(Section, FilenameFallbackIsNotResolved) {
  EXPECT_EQ(kLaser.read_filename("map_file", "default.pgm"), "default.pgm");
}

TEST(Section, FilenameOfARelativeConfigPathStartsAtTheCurrentDirectory) {
  const Section bare = first_section("x:0 ( f \"map.pgm\" )", "amcl.cfg");
  EXPECT_EQ(bare.read_filename("f", ""), (std::filesystem::current_path() / "map.pgm").string());
  const Section nested = first_section("x:0 ( f \"map.pgm\" )", "cfg/amcl.cfg");
  EXPECT_EQ(nested.read_filename("f", ""),
            (std::filesystem::current_path() / "cfg" / "map.pgm").string());
}

TEST(Section, FilenameFromAnIncludedFileIsRelativeToThatFile) {
  const std::string text = "include \"" + data_path("includes/sub/robot.cfg") + "\"\n";
  ParsedConfig parsed = parse_text(text, "/elsewhere/main.cfg");
  // sub/robot.cfg includes a define (no section) and declares sonar:0.
  const Section sonar(std::move(parsed.sections.at(0)), parsed.units);
  EXPECT_EQ(sonar.read_filename("map", ""), data_path("includes/sub/maps/cave.pgm"));
}

TEST(Section, ReadsMarkPropertiesUsed) {
  const Section section = first_section("laser:0 ( a 1 b 2 c [ 1 ] d 4 e 5 f 6 )");
  const auto used = [&](const char* name) { return section.property(name)->used; };
  EXPECT_TRUE(section.has("a"));
  EXPECT_FALSE(used("a"));  // has() is not a read
  (void)section.read_int("a", 0);
  (void)section.tuple_size("c");
  (void)section.read_tuple_float("d", 5, 0.0);  // out of range still counts
  (void)section.read_filename("e", "");
  EXPECT_TRUE(used("a"));
  EXPECT_FALSE(used("b"));
  EXPECT_TRUE(used("c"));
  EXPECT_TRUE(used("d"));
  EXPECT_TRUE(used("e"));
  EXPECT_FALSE(used("f"));
}

}  // namespace section_test
}  // namespace playerkit::config
