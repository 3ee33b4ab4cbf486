#include "field_path.hpp"

#include <gtest/gtest.h>

namespace playerkit::tools {
namespace field_path_test {

using nlohmann::json;

const json kLaser = json::parse(R"({"range_count":3,"ranges":[1000,1500,2000],"pose":{"px":5,"list":[7]}})");

TEST(FieldPathTest, ParsesDottedSegments) {
  const auto path = FieldPath::parse("pose.list.0");
  EXPECT_EQ(path.text(), "pose.list.0");
  EXPECT_EQ(path.segments(), (std::vector<std::string>{"pose", "list", "0"}));
  EXPECT_EQ(FieldPath::parse("range_count").segments().size(), 1u);
}

TEST(FieldPathTest, RefusesEmptyPathsAndSegments) {
  for (const char* bad : {"", ".", "a..b", ".a", "a."}) {
    EXPECT_THROW(FieldPath::parse(bad), FieldPathError) << bad;
  }
  try {
    FieldPath::parse("ranges..0");
  } catch (const FieldPathError& e) {
    EXPECT_NE(std::string(e.what()).find("'ranges..0'"), std::string::npos) << e.what();
  }
}

TEST(FieldPathTest, FindsObjectKeysAndArrayElements) {
  EXPECT_EQ(*FieldPath::parse("range_count").find_in(kLaser), 3);
  EXPECT_EQ(*FieldPath::parse("ranges.0").find_in(kLaser), 1000);
  EXPECT_EQ(*FieldPath::parse("ranges.2").find_in(kLaser), 2000);
  EXPECT_EQ(*FieldPath::parse("pose.px").find_in(kLaser), 5);
  EXPECT_EQ(*FieldPath::parse("pose.list.0").find_in(kLaser), 7);
  EXPECT_EQ(*FieldPath::parse("ranges").find_in(kLaser), json::array({1000, 1500, 2000}));
}

TEST(FieldPathTest, MissingPathsFindNothing) {
  EXPECT_EQ(FieldPath::parse("ranges.3").find_in(kLaser), nullptr);  // past the end
  EXPECT_EQ(FieldPath::parse("ranges.x").find_in(kLaser), nullptr);  // not an index
  EXPECT_EQ(FieldPath::parse("ranges.-1").find_in(kLaser), nullptr);
  EXPECT_EQ(FieldPath::parse("range_count.0").find_in(kLaser), nullptr);  // below a number
  EXPECT_EQ(FieldPath::parse("charge").find_in(kLaser), nullptr);
}

TEST(FieldPathTest, NumericKeysOfObjectsAreKeys) {
  const json data = json::parse(R"({"7":{"a":1}})");
  EXPECT_EQ(*FieldPath::parse("7.a").find_in(data), 1);
}

TEST(FlattenTest, NamesEveryLeafByItsDottedPath) {
  const auto columns = flatten(kLaser);
  const std::vector<NamedValue> expected{
      {"pose.list.0", 7}, {"pose.px", 5},     {"range_count", 3},
      {"ranges.0", 1000}, {"ranges.1", 1500}, {"ranges.2", 2000},
  };
  EXPECT_EQ(columns, expected);
}

TEST(FlattenTest, KeepsAPrefixAndDropsEmptyContainers) {
  EXPECT_EQ(flatten(json::array({1, 2}), "ranges"),
            (std::vector<NamedValue>{{"ranges.0", 1}, {"ranges.1", 2}}));
  EXPECT_TRUE(flatten(json::parse(R"({"ranges":[],"pose":{}})")).empty());
  EXPECT_EQ(flatten(json("text"), "name"), (std::vector<NamedValue>{{"name", "text"}}));
}

TEST(SelectFieldsTest, KeepsTheOrderGivenAndNullsWhatIsMissing) {
  const std::vector<FieldPath> fields{FieldPath::parse("ranges.1"), FieldPath::parse("nope"),
                                      FieldPath::parse("range_count")};
  const std::vector<NamedValue> expected{{"ranges.1", 1500}, {"nope", nullptr}, {"range_count", 3}};
  EXPECT_EQ(select_fields(kLaser, fields), expected);
  const auto missing = missing_fields(kLaser, fields);
  ASSERT_EQ(missing.size(), 1u);
  EXPECT_EQ(missing[0].text(), "nope");
}

TEST(DescribeFieldsTest, ListsKeysWithArrayBounds) {
  EXPECT_EQ(describe_fields(kLaser),
            "pose (object: pose.<field>), range_count, ranges (array of 3: ranges.0 ... ranges.2)");
  EXPECT_EQ(describe_fields(json::object()), "(no fields)");
  EXPECT_EQ(describe_fields(json::parse(R"({"msg":[]})")), "msg (empty array)");
}

}  // namespace field_path_test
}  // namespace playerkit::tools
