#pragma once
// The whitespace-separated fields of one text log line, with their columns, and
// strict conversions that throw LogParseError pointing at the offending field.
// (1.5's readlog used atoi/atof, which read "abc" as 0; here that is an error.)

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "log/log_parse_error.hpp"
#include "protocol/message.hpp"

namespace playerkit::log {

class LineFields {
 public:
  // A trailing "\n" or "\r\n" is dropped; file and line only go into errors.
  LineFields(std::string_view text, std::string_view file, int line);

  std::size_t size() const { return fields_.size(); }
  std::string_view text_view(std::size_t i) const { return fields_[i].text; }
  std::string text(std::size_t i) const { return std::string(fields_[i].text); }
  int column(std::size_t i) const { return fields_[i].column; }

  // Fails at the end of the line, naming `what`, when field i is missing.
  void at(std::size_t i, std::string_view what) const;
  // Fails at field `end` when the line goes on past `after`.
  void expect_end(std::size_t end, std::string_view after) const;

  [[noreturn]] void fail(std::size_t i, const std::string& message) const;
  [[noreturn]] void fail_at_end(const std::string& message) const;

  // "1086000000.250" exactly: seconds and the fraction rounded to microseconds.
  protocol::Timestamp timestamp(std::size_t i, std::string_view what) const;
  // A finite decimal number; a leading '+' is allowed (the "%+07.3f" fields).
  double real(std::size_t i, std::string_view what) const;
  // Like real, but exponents are allowed too ("2.35e-11"): for values that
  // span many magnitudes, such as covariances.
  double scientific(std::size_t i, std::string_view what) const;

  // A whole number that fits Int.
  template <std::integral Int>
  Int integer(std::size_t i, std::string_view what) const {
    return static_cast<Int>(integer_in(i, what, std::numeric_limits<Int>::min(),
                                       std::numeric_limits<Int>::max()));
  }

  // A number in file units times wire_per_file_unit, rounded to the nearest
  // wire unit, which must fit Int.
  template <std::integral Int>
  Int wire(std::size_t i, std::string_view what, double wire_per_file_unit,
           std::string_view wire_unit) const {
    return static_cast<Int>(rounded_in(i, what, wire_per_file_unit, wire_unit,
                                       static_cast<double>(std::numeric_limits<Int>::min()),
                                       static_cast<double>(std::numeric_limits<Int>::max())));
  }

 private:
  struct Field {
    std::string_view text;
    int column = 0;  // 1-based
  };

  double number(std::size_t i, std::string_view what, bool allow_exponent) const;
  long long integer_in(std::size_t i, std::string_view what, long long min, long long max) const;
  double rounded_in(std::size_t i, std::string_view what, double wire_per_file_unit,
                    std::string_view wire_unit, double min, double max) const;

  std::string file_;
  int line_;
  int end_column_;
  std::vector<Field> fields_;
};

// 'text' for an error message: control characters escaped, long text cut
// (text::excerpt).
std::string quoted_excerpt(std::string_view text);

}  // namespace playerkit::log
