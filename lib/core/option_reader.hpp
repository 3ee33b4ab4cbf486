#pragma once
// Reading a driver's options with the checks every driver needs, each error
// a config::ConfigError at the option's own file:line:col:
//
//   core::OptionReader options(context.section, "sicklms200");
//   const int rate = options.choice("rate", 38400, {9600, 38400, 500000});
//   const double range = options.number("max_range", 8.0, 0.0, 80.0);
//   const int index = options.index("laser_index", 0);
//
//   sicklms200.cfg:4:8: sicklms200: rate must be one of 9600, 38400, 500000 (got 19200)
//
// Names may come with legacy aliases, the preferred name first: the first one
// present in the section is read ({"laser_max_beams", "laser_max_samples"}).

#include <cstdint>
#include <initializer_list>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/errors.hpp"
#include "config/section.hpp"

namespace playerkit::core {

class OptionReader {
 public:
  using Names = std::initializer_list<std::string_view>;

  OptionReader(const config::Section& section, std::string driver_name);

  [[nodiscard]] const config::Section& section() const { return section_; }
  [[nodiscard]] bool has(Names names) const;

  // Strings. An empty value is refused unless allow_empty.
  [[nodiscard]] std::string text(Names names, std::string_view fallback, bool allow_empty = false) const;
  // Relative to the file the value is written in (config::Section::read_filename).
  [[nodiscard]] std::string filename(Names names, std::string_view fallback) const;
  // One of `allowed` (exact match); the error lists them.
  [[nodiscard]] std::string word(Names names, std::string_view fallback,
                                 std::initializer_list<std::string_view> allowed) const;

  // Numbers, checked to lie in [minimum, maximum].
  [[nodiscard]] int integer(Names names, int fallback, int minimum, int maximum) const;
  [[nodiscard]] double number(Names names, double fallback, double minimum, double maximum) const;
  // In the file's length unit, returned in metres; the range is in metres.
  [[nodiscard]] double length(Names names, double fallback, double minimum, double maximum) const;
  // In the file's angle unit, returned in radians; the range is in radians.
  [[nodiscard]] double angle(Names names, double fallback, double minimum, double maximum) const;
  // 0 or 1.
  [[nodiscard]] bool flag(Names names, bool fallback) const;
  // One of `allowed` (baud rates, resolutions).
  [[nodiscard]] int choice(Names names, int fallback, std::initializer_list<int> allowed) const;
  // A device index (>= 0) and a TCP/UDP port number (1..65535).
  [[nodiscard]] int index(Names names, int fallback) const;
  [[nodiscard]] int network_port(Names names, int fallback) const;

  // Tuples: [x y yaw] poses and the like. Each element is checked as above.
  [[nodiscard]] std::size_t tuple_size(Names names) const;
  [[nodiscard]] double tuple_length(Names names, std::size_t element, double fallback) const;
  [[nodiscard]] double tuple_angle(Names names, std::size_t element, double fallback) const;

  // The location of the option's value (or of the section, when it is absent).
  [[nodiscard]] config::SourceLocation where(Names names, std::size_t element = 0) const;
  // "<driver>: <name> <message>" at the option's value.
  [[noreturn]] void fail(Names names, const std::string& message, std::size_t element = 0) const;

 private:
  // The first of `names` present in the section, else the first name.
  [[nodiscard]] std::string_view present(Names names) const;
  [[nodiscard]] double checked(Names names, double value, double minimum, double maximum,
                               std::string_view shown) const;

  const config::Section& section_;
  std::string driver_;
};

}  // namespace playerkit::core
