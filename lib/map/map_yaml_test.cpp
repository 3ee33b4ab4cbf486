// map.yaml written by format_map_yaml and read back by parse_map_yaml.

#include "map/map_yaml.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace playerkit::map {
namespace map_yaml_test {

MapYaml description_of(const std::filesystem::path& image) {
  MapYaml description;
  description.image = image;
  description.resolution = 0.05;
  description.origin = {-1.5, 2.0};
  description.negate = true;
  return description;
}

void expect_same(const MapYaml& a, const MapYaml& b) {
  EXPECT_EQ(a.image, b.image);
  EXPECT_EQ(a.resolution, b.resolution);
  EXPECT_EQ(a.origin, b.origin);
  EXPECT_EQ(a.negate, b.negate);
  EXPECT_EQ(a.occupied_threshold, b.occupied_threshold);
  EXPECT_EQ(a.free_threshold, b.free_threshold);
}

// Found by the map_yaml fuzz target: a line break in the image's name (a
// "\n" escape in a quoted value read) was written raw, which cut the quoted
// value and made the file one its own reader refused.
TEST(MapYamlFormat, AnImageNameWithALineBreakIsWrittenAsAnEscape) {
  const MapYaml description = description_of("/maps/two\nlines.pgm");
  const std::string text = format_map_yaml(description);
  EXPECT_EQ(text.substr(0, text.find('\n')), R"(image: "/maps/two\nlines.pgm")");
  EXPECT_EQ(std::count(text.begin(), text.end(), '\n'), 6) << text;  // one line per key
  expect_same(parse_map_yaml(text, "/maps/map.yaml"), description);
}

TEST(MapYamlFormat, QuotesBackslashesAndOtherBytesSurviveARoundTrip) {
  using namespace std::string_literals;
  for (const std::string& name : {"/maps/plain-name_1.pgm"s, "/maps/with space.pgm"s, "/maps/\"quoted\".pgm"s,
                                  "/maps/back\\slash.pgm"s, "/maps/tab\tand # hash.pgm"s,
                                  "/maps/nul\0and\r\xff.pgm"s, "/maps/ends\n"s}) {
    const MapYaml description = description_of(name);
    const std::string text = format_map_yaml(description);
    SCOPED_TRACE(text);
    expect_same(parse_map_yaml(text, "/maps/map.yaml"), description);
  }
}

}  // namespace map_yaml_test
}  // namespace playerkit::map
