#pragma once
// Reading a driver's options with the checks every driver needs, each error
// a config::ConfigError at the option's own file:line:col.
//
// With the driver's OptionSchema (option_schema.hpp) an option is read by
// name, with the default and checks declared there:
//
//   core::OptionReader options(context.section, "sicklms200", schema);
//   const int rate = options.integer("rate");
//   const double range = options.length("max_range");
//
//   sicklms200.cfg:4:8: sicklms200: rate must be one of 9600, 38400, 500000 (got 19200)
//
// Without one, each read names its fallback and checks (drivers not yet
// declaring a schema): options.choice({"rate"}, 38400, {9600, 38400, 500000}).
//
// Names may come with legacy aliases, the preferred name first: the first one
// present in the section is read ({"laser_max_beams", "laser_max_samples"}).

#include <chrono>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "config/errors.hpp"
#include "config/section.hpp"
#include "core/option_schema.hpp"

namespace playerkit::core {

class OptionReader {
 public:
  using Names = std::initializer_list<std::string_view>;

  OptionReader(const config::Section& section, std::string driver_name);
  // `schema` must outlive the reader.
  OptionReader(const config::Section& section, std::string driver_name, const OptionSchema& schema);

  [[nodiscard]] const config::Section& section() const { return section_; }
  [[nodiscard]] const std::string& driver_name() const { return driver_; }
  [[nodiscard]] bool has(Names names) const;

  // --- Options declared in the schema, by name (or alias). Reading an
  // undeclared option, or one of another type, is a programming error
  // (std::logic_error).
  [[nodiscard]] int integer(std::string_view name) const;  // integer, choice
  [[nodiscard]] double number(std::string_view name) const;
  [[nodiscard]] double length(std::string_view name) const;  // metres
  [[nodiscard]] double angle(std::string_view name) const;   // radians
  [[nodiscard]] bool flag(std::string_view name) const;
  [[nodiscard]] std::string text(std::string_view name) const;  // text, filename, word, link_port
  // A number option in seconds, as a duration.
  [[nodiscard]] std::chrono::milliseconds seconds(std::string_view name) const;
  // Element of a tuple option, in metres or radians as the element's type says.
  [[nodiscard]] double element(std::string_view name, std::size_t index) const;
  [[nodiscard]] bool has(std::string_view name) const;
  // Reads every declared option the section writes, so that each bad value
  // is an error now (instantiate_devices calls it before the driver's factory).
  void validate() const;

  // --- Reads that name their own fallback and checks.
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
  using NameList = std::span<const std::string_view>;
  static NameList list(Names names) { return {names.begin(), names.size()}; }

  // The declared option `name`, which must be of one of `types`.
  [[nodiscard]] const OptionSpec& declared(std::string_view name, std::initializer_list<OptionType> types) const;
  [[nodiscard]] double read_number(const OptionSpec& spec) const;
  [[nodiscard]] std::string read_text(const OptionSpec& spec) const;
  [[nodiscard]] double read_element(const OptionSpec& spec, std::size_t index) const;

  // The first of `names` present in the section, else the first name.
  [[nodiscard]] std::string_view present(NameList names) const;
  [[nodiscard]] bool has_any(NameList names) const;
  [[nodiscard]] config::SourceLocation where_at(NameList names, std::size_t element) const;
  [[noreturn]] void fail_at(NameList names, const std::string& message, std::size_t element = 0) const;
  [[nodiscard]] double checked(NameList names, double value, double minimum, double maximum,
                               std::string_view shown) const;

  [[nodiscard]] std::string text_at(NameList names, std::string_view fallback, bool allow_empty) const;
  [[nodiscard]] std::string filename_at(NameList names, std::string_view fallback, bool allow_empty) const;
  [[nodiscard]] std::string word_at(NameList names, std::string_view fallback,
                                 std::span<const std::string_view> allowed) const;
  [[nodiscard]] int integer_at(NameList names, int fallback, int minimum, int maximum) const;
  [[nodiscard]] double number_at(NameList names, double fallback, double minimum, double maximum) const;
  [[nodiscard]] double length_at(NameList names, double fallback, double minimum, double maximum) const;
  [[nodiscard]] double angle_at(NameList names, double fallback, double minimum, double maximum) const;
  [[nodiscard]] bool flag_at(NameList names, bool fallback) const;
  [[nodiscard]] int choice_at(NameList names, int fallback, std::span<const int> allowed) const;
  [[nodiscard]] double tuple_length_at(NameList names, std::size_t element, double fallback) const;
  [[nodiscard]] double tuple_angle_at(NameList names, std::size_t element, double fallback) const;
  [[nodiscard]] double tuple_number_at(NameList names, std::size_t element, double fallback) const;

  const config::Section& section_;
  std::string driver_;
  const OptionSchema* schema_ = nullptr;
};

}  // namespace playerkit::core
