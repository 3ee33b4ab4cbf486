#include "config/closest_name.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

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


TEST(EditDistance, StopsAtTheLimit) {
  EXPECT_EQ(edit_distance("sicklms2000", "sicklms200", 1), 1u);
  EXPECT_EQ(edit_distance("gps", "ptz", 1), 2u);  // limit + 1: more than the limit
  EXPECT_EQ(edit_distance("gps", "ptz", 3), 3u);
  EXPECT_EQ(edit_distance("a", "abcdef", 2), 3u);  // the lengths alone say it
  // Every pair of a small alphabet: the cut-off never changes a distance within the limit.
  const std::string letters = "abc";
  std::vector<std::string> words{""};
  for (int length = 1; length <= 4; ++length) {
    const std::size_t start = words.size();
    for (std::size_t w = 0; w < start; ++w) {
      if (words[w].size() + 1 != static_cast<std::size_t>(length)) continue;
      for (char c : letters) words.push_back(words[w] + c);
    }
  }
  for (const auto& a : words) {
    for (const auto& b : words) {
      const std::size_t full = edit_distance(a, b);
      for (std::size_t limit = 0; limit <= 4; ++limit) {
        ASSERT_EQ(edit_distance(a, b, limit), std::min(full, limit + 1)) << a << " " << b << " " << limit;
      }
    }
  }
}

TEST(ClosestName, LongWordsGetNoSuggestion) {
  constexpr std::array<std::string_view, 2> names = {"sicklms200", "laser"};
  const std::string typo = "sicklms2000";
  EXPECT_EQ(closest_name(typo, names), "sicklms200");
  EXPECT_EQ(closest_name(std::string(kMaxSuggestedNameBytes + 1, 'a'), names), std::nullopt);
  // A 1 MB name that is all but one of its bytes a near miss is answered at once.
  EXPECT_EQ(closest_name("sicklms200" + std::string(1'000'000, 'x'), names), std::nullopt);
}

}  // namespace closest_name_test
}  // namespace playerkit::config
