#pragma once
// Dotted paths into the JSON of a message's data, as --field takes them:
// "range_count", "ranges.0", "pose.px". A numeric segment indexes an array;
// on an object it is an ordinary key.
//
// Also the flattening CSV needs: {"ranges":[1,2],"count":2} becomes the
// columns ranges.0, ranges.1, count.

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace playerkit::tools {

class FieldPathError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

class FieldPath {
 public:
  // Throws FieldPathError for an empty path or an empty segment ("a..b", ".a").
  static FieldPath parse(std::string_view text);

  [[nodiscard]] const std::string& text() const { return text_; }
  [[nodiscard]] const std::vector<std::string>& segments() const { return segments_; }
  // The value at this path, or nullptr when the data has none there.
  [[nodiscard]] const nlohmann::json* find_in(const nlohmann::json& data) const;

  friend bool operator==(const FieldPath&, const FieldPath&) = default;

 private:
  std::string text_;
  std::vector<std::string> segments_;
};

// One named value: a column of CSV, a "name=value" of text.
using NamedValue = std::pair<std::string, nlohmann::json>;

// Every leaf (number, string, boolean, null) of `value`, named by its dotted
// path below `prefix`, in document order. Empty arrays and objects have no leaves.
std::vector<NamedValue> flatten(const nlohmann::json& value, const std::string& prefix = {});

// The requested fields of `data`, named by their paths, in the order given;
// a field the data lacks comes back as null.
std::vector<NamedValue> select_fields(const nlohmann::json& data, const std::vector<FieldPath>& fields);

// The fields `data` lacks (for the error at a device's first message).
std::vector<FieldPath> missing_fields(const nlohmann::json& data, const std::vector<FieldPath>& fields);

// What the data offers, for error messages: "count, ranges (array of 361: ranges.0 ... ranges.360)".
std::string describe_fields(const nlohmann::json& data);

}  // namespace playerkit::tools
