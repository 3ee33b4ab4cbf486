#pragma once
// A driver's options declared once: name, legacy aliases, type, default,
// unit, range or choices, and a line of documentation. Everything else is
// derived from that declaration, so it cannot drift:
//
//   * OptionReader(section, driver, schema) reads each option with the
//     declared default and checks, errors at the value's file:line:col;
//   * instantiate_devices (and so `player-serve --check`) validates every
//     option a section writes before the driver's factory runs;
//   * `player-drivers info` shows docs() and a README shows markdown().
//
//   const core::OptionSchema schema{
//       core::OptionSpec::choice("rate", 38400, {9600, 38400, 500000}).unit("baud").doc("line speed"),
//       core::OptionSpec::number("reply_timeout", 1.0, 0.05, 30.0).unit("s").doc("per reply"),
//   };
//
// Checks that tie several options together (a field of view that limits the
// angles) stay in the driver's reading code, through OptionReader::fail.

#include <functional>
#include <initializer_list>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::core {

// One row of `player-drivers info`: enough to write a configuration section
// without the manual. Drivers without a schema write these by hand.
struct OptionDoc {
  std::string name;           // "rate"; legacy aliases after a slash: "laser_max_beams/laser_max_samples"
  std::string type;           // "int", "float", "length", "angle", "string", "filename", "tuple", "port"
  std::string default_value;  // as it would be written in a .cfg
  std::string unit;           // "baud", "m", "deg", "mm/s"; empty when none
  std::string summary;        // one line; allowed values where they are few
};

enum class OptionType {
  integer,    // an int within [minimum, maximum]
  number,     // a float within [minimum, maximum]
  length,     // in the file's length unit, read in metres; range in metres
  angle,      // in the file's angle unit, read in radians; range in radians
  flag,       // 0 or 1
  text,       // a string; empty only when allowed
  filename,   // relative to the file it is written in
  word,       // one of a few strings
  choice,     // one of a few ints (baud rates, resolutions)
  tuple,      // [a b c], each element a number, length or angle
  link_port,  // a serial device or tcp:HOST:PORT (links::port_option)
};

// For text-like options: the reason a value is refused ("is not an IPv4
// address"), or empty when it is fine. Written after "<driver>: <name> ".
using TextCheck = std::function<std::string(std::string_view value)>;

class OptionSpec {
 public:
  static OptionSpec integer(std::string name, int fallback, int minimum, int maximum);
  static OptionSpec number(std::string name, double fallback, double minimum, double maximum);
  static OptionSpec length(std::string name, double fallback_metres, double minimum, double maximum);
  static OptionSpec angle(std::string name, double fallback_radians, double minimum, double maximum);
  static OptionSpec flag(std::string name, bool fallback);
  static OptionSpec text(std::string name, std::string fallback);
  static OptionSpec filename(std::string name, std::string fallback);
  static OptionSpec word(std::string name, std::string fallback, std::vector<std::string> words);
  static OptionSpec choice(std::string name, int fallback, std::vector<int> choices);
  // Elements: OptionType::number, length or angle; the fallback per element
  // in metres and radians.
  static OptionSpec tuple(std::string name, std::vector<OptionType> elements, std::vector<double> fallback);
  // Use links::port_option, which brings the address parser.
  static OptionSpec link_port(std::string name, std::string fallback, TextCheck check);

  // Chained while declaring: OptionSpec::flag("invert", false).doc("...").
  OptionSpec&& unit(std::string unit) &&;
  OptionSpec&& doc(std::string doc) &&;
  OptionSpec&& aliases(std::vector<std::string> older_names) &&;
  // The default as documented, when it depends on other options
  // ("180 (100 with resolution 25)"); the reader still uses the fallback.
  OptionSpec&& shown_default(std::string text) &&;
  OptionSpec&& allow_empty() &&;
  // An extra check of text, filename and link_port values.
  OptionSpec&& check(TextCheck check) &&;

  [[nodiscard]] const std::string& name() const { return name_; }
  // The name first, then the aliases: the reader takes the first present.
  [[nodiscard]] std::vector<std::string_view> names() const;
  [[nodiscard]] OptionType type() const { return type_; }
  [[nodiscard]] const std::string& unit() const { return unit_; }
  [[nodiscard]] const std::string& doc() const { return doc_; }
  [[nodiscard]] double minimum() const { return minimum_; }
  [[nodiscard]] double maximum() const { return maximum_; }
  [[nodiscard]] double number_fallback() const { return number_fallback_; }
  [[nodiscard]] const std::string& text_fallback() const { return text_fallback_; }
  [[nodiscard]] const std::vector<double>& tuple_fallback() const { return tuple_fallback_; }
  [[nodiscard]] const std::vector<OptionType>& elements() const { return elements_; }
  [[nodiscard]] const std::vector<int>& choices() const { return choices_; }
  [[nodiscard]] const std::vector<std::string>& words() const { return words_; }
  [[nodiscard]] bool empty_allowed() const { return allow_empty_; }
  [[nodiscard]] const TextCheck& text_check() const { return check_; }

  // As written in a .cfg: "38400", "\"/dev/ttyS1\"", "[0 0 0]" (angles in
  // degrees), or the shown_default.
  [[nodiscard]] std::string default_text() const;
  // "9600, 38400 or 500000", "0 to 3600", "0 or 1"; empty when anything goes.
  [[nodiscard]] std::string allowed_text() const;
  // "int", "float", "length", "angle", "string", "filename", "tuple", "port".
  [[nodiscard]] std::string type_text() const;

  [[nodiscard]] const std::vector<std::string>& aliases() const { return aliases_; }

 private:
  OptionSpec(std::string name, OptionType type);

  std::string name_;
  std::vector<std::string> aliases_;
  OptionType type_;
  std::string unit_;
  std::string doc_;
  std::string shown_default_;
  double minimum_ = 0.0;
  double maximum_ = 0.0;
  double number_fallback_ = 0.0;
  std::string text_fallback_;
  std::vector<double> tuple_fallback_;
  std::vector<OptionType> elements_;
  std::vector<int> choices_;
  std::vector<std::string> words_;
  bool allow_empty_ = false;
  TextCheck check_;
};

class OptionSchema {
 public:
  OptionSchema() = default;
  // Throws std::logic_error when a name or alias is declared twice.
  OptionSchema(std::initializer_list<OptionSpec> options);
  void add(OptionSpec option);
  // Every option of `other` after this one's (a robot's options, then a device's).
  void add(const OptionSchema& other);

  // By name or alias; nullptr when not declared.
  [[nodiscard]] const OptionSpec* find(std::string_view name) const;
  [[nodiscard]] const std::vector<OptionSpec>& options() const { return options_; }
  [[nodiscard]] bool empty() const { return options_.empty(); }

  // The rows `player-drivers info` shows, in declaration order.
  [[nodiscard]] std::vector<OptionDoc> docs() const;
  // A Markdown table of the options, for a driver's README.
  [[nodiscard]] std::string markdown() const;

 private:
  std::vector<OptionSpec> options_;
};

}  // namespace playerkit::core
