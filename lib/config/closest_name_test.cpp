#include "config/closest_name.hpp"

#include <gtest/gtest.h>

#include <array>

namespace playerkit::config {
namespace closest_name_test {

TEST(EditDistance, CountsInsertionsDeletionsReplacementsAndSwaps) {
  EXPECT_EQ(edit_distance("laser", "laser"), 0u);
  EXPECT_EQ(edit_distance("lazer", "laser"), 1u);             // replace
  EXPECT_EQ(edit_distance("sicklms2000", "sicklms200"), 1u);  // delete
  EXPECT_EQ(edit_distance("sonr", "sonar"), 1u);              // insert
  EXPECT_EQ(edit_distance("posiiton", "position"), 1u);       // swap
  EXPECT_EQ(edit_distance("", "abc"), 3u);
  EXPECT_EQ(edit_distance("gps", "ptz"), 3u);
}

TEST(ClosestName, SuggestsOnlyPlausibleTypos) {
  constexpr std::array<std::string_view, 4> names = {"laser", "sonar", "position", "ptz"};
  EXPECT_EQ(closest_name("lazer", names), "laser");
  EXPECT_EQ(closest_name("positoin", names), "position");
  EXPECT_EQ(closest_name("pzt", names), "ptz");
  EXPECT_EQ(closest_name("camera", names), std::nullopt);
  EXPECT_EQ(closest_name("", names), std::nullopt);
}

TEST(ClosestName, TiesGoToTheEarlierCandidate) {
  constexpr std::array<std::string_view, 2> names = {"abd", "abe"};
  EXPECT_EQ(closest_name("abc", names), "abd");
}

}  // namespace closest_name_test
}  // namespace playerkit::config
