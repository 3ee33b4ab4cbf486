#include "core/option_reader.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace playerkit::core {

namespace {

template <class Items>
std::string join(const Items& items) {
  std::ostringstream out;
  bool first = true;
  for (const auto& item : items) {
    if (!first) out << ", ";
    out << item;
    first = false;
  }
  return out.str();
}

std::string shown_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

bool is_one_of(OptionType type, std::initializer_list<OptionType> types) {
  return std::find(types.begin(), types.end(), type) != types.end();
}

}  // namespace

OptionReader::OptionReader(const config::Section& section, std::string driver_name)
    : section_(section), driver_(std::move(driver_name)) {}

OptionReader::OptionReader(const config::Section& section, std::string driver_name, const OptionSchema& schema)
    : section_(section), driver_(std::move(driver_name)), schema_(&schema) {}

// --- Options of the schema.

const OptionSpec& OptionReader::declared(std::string_view name, std::initializer_list<OptionType> types) const {
  const OptionSpec* spec = schema_ == nullptr ? nullptr : schema_->find(name);
  if (spec == nullptr) {
    throw std::logic_error(driver_ + ": option " + std::string(name) + " is not declared in the driver's schema");
  }
  if (!is_one_of(spec->type(), types)) {
    throw std::logic_error(driver_ + ": option " + std::string(name) + " is declared as " + spec->type_text() +
                           ", not read as one");
  }
  return *spec;
}

double OptionReader::read_number(const OptionSpec& spec) const {
  const std::vector<std::string_view> names = spec.names();
  const double fallback = spec.number_fallback();
  switch (spec.type()) {
    case OptionType::integer:
      return integer_at(names, static_cast<int>(fallback), static_cast<int>(spec.minimum()),
                        static_cast<int>(spec.maximum()));
    case OptionType::choice: return choice_at(names, static_cast<int>(fallback), spec.choices());
    case OptionType::flag: return flag_at(names, fallback != 0.0) ? 1.0 : 0.0;
    case OptionType::number: return number_at(names, fallback, spec.minimum(), spec.maximum());
    case OptionType::length: return length_at(names, fallback, spec.minimum(), spec.maximum());
    case OptionType::angle: return angle_at(names, fallback, spec.minimum(), spec.maximum());
    default: throw std::logic_error(driver_ + ": option " + spec.name() + " is not a number");
  }
}

std::string OptionReader::read_text(const OptionSpec& spec) const {
  const std::vector<std::string_view> names = spec.names();
  std::string value;
  switch (spec.type()) {
    case OptionType::text:
    case OptionType::link_port: value = text_at(names, spec.text_fallback(), spec.empty_allowed()); break;
    case OptionType::filename: value = filename_at(names, spec.text_fallback(), spec.empty_allowed()); break;
    case OptionType::word: {
      const std::vector<std::string_view> words(spec.words().begin(), spec.words().end());
      return word_at(names, spec.text_fallback(), words);
    }
    default: throw std::logic_error(driver_ + ": option " + spec.name() + " is not text");
  }
  if (spec.text_check() && has_any(names)) {
    if (const std::string problem = spec.text_check()(value); !problem.empty()) fail_at(names, problem);
  }
  return value;
}

double OptionReader::read_element(const OptionSpec& spec, std::size_t index) const {
  const std::vector<std::string_view> names = spec.names();
  const double fallback = index < spec.tuple_fallback().size() ? spec.tuple_fallback()[index] : 0.0;
  const OptionType type = index < spec.elements().size() ? spec.elements()[index] : OptionType::number;
  switch (type) {
    case OptionType::length: return tuple_length_at(names, index, fallback);
    case OptionType::angle: return tuple_angle_at(names, index, fallback);
    default: return tuple_number_at(names, index, fallback);
  }
}

int OptionReader::integer(std::string_view name) const {
  return static_cast<int>(read_number(declared(name, {OptionType::integer, OptionType::choice})));
}

double OptionReader::number(std::string_view name) const {
  return read_number(declared(name, {OptionType::number}));
}

double OptionReader::length(std::string_view name) const {
  return read_number(declared(name, {OptionType::length}));
}

double OptionReader::angle(std::string_view name) const { return read_number(declared(name, {OptionType::angle})); }

bool OptionReader::flag(std::string_view name) const {
  return read_number(declared(name, {OptionType::flag})) != 0.0;
}

std::string OptionReader::text(std::string_view name) const {
  return read_text(
      declared(name, {OptionType::text, OptionType::filename, OptionType::word, OptionType::link_port}));
}

std::chrono::milliseconds OptionReader::seconds(std::string_view name) const {
  const OptionSpec& spec = declared(name, {OptionType::number});
  if (spec.unit() != "s") throw std::logic_error(driver_ + ": option " + spec.name() + " is not in seconds");
  return std::chrono::milliseconds(std::lround(read_number(spec) * 1000.0));
}

double OptionReader::element(std::string_view name, std::size_t index) const {
  const OptionSpec& spec = declared(name, {OptionType::tuple});
  if (index >= spec.elements().size()) {
    throw std::logic_error(driver_ + ": option " + spec.name() + " has no element " + std::to_string(index));
  }
  return read_element(spec, index);
}

bool OptionReader::has(std::string_view name) const {
  const OptionSpec* spec = schema_ == nullptr ? nullptr : schema_->find(name);
  if (spec == nullptr) return section_.has(name);
  return has_any(spec->names());
}

void OptionReader::validate() const {
  if (schema_ == nullptr) return;
  for (const OptionSpec& spec : schema_->options()) {
    if (!has_any(spec.names())) continue;
    switch (spec.type()) {
      case OptionType::text:
      case OptionType::filename:
      case OptionType::word:
      case OptionType::link_port: (void)read_text(spec); break;
      case OptionType::tuple:
        for (std::size_t i = 0; i < spec.elements().size(); ++i) (void)read_element(spec, i);
        break;
      default: (void)read_number(spec); break;
    }
  }
}

// --- The checks themselves, on a list of names.

std::string_view OptionReader::present(NameList names) const {
  for (std::string_view name : names) {
    if (section_.has(name)) return name;
  }
  return names.front();
}

bool OptionReader::has_any(NameList names) const {
  return std::any_of(names.begin(), names.end(), [this](std::string_view name) { return section_.has(name); });
}

config::SourceLocation OptionReader::where_at(NameList names, std::size_t element) const {
  const config::Property* property = section_.property(present(names));
  if (property == nullptr) return section_.where();
  if (element < property->values.size()) return property->values[element].where;
  return property->where;
}

void OptionReader::fail_at(NameList names, const std::string& message, std::size_t element) const {
  throw config::ConfigError(where_at(names, element), driver_ + ": " + std::string(present(names)) + " " + message);
}

std::string OptionReader::text_at(NameList names, std::string_view fallback, bool allow_empty) const {
  std::string value = section_.read_string(present(names), fallback);
  if (value.empty() && !allow_empty) fail_at(names, "must not be empty");
  return value;
}

std::string OptionReader::filename_at(NameList names, std::string_view fallback, bool allow_empty) const {
  // As written: an empty name would otherwise come back as the file's folder.
  const bool written_empty = has_any(names) && section_.read_string(present(names), "").empty();
  std::string value = section_.read_filename(present(names), fallback);
  if ((value.empty() || written_empty) && !allow_empty) fail_at(names, "must name a file");
  return value;
}

std::string OptionReader::word_at(NameList names, std::string_view fallback,
                                  std::span<const std::string_view> allowed) const {
  std::string value = section_.read_string(present(names), fallback);
  for (std::string_view candidate : allowed) {
    if (value == candidate) return value;
  }
  fail_at(names, "must be one of " + join(allowed) + " (got \"" + value + "\")");
}

double OptionReader::checked(NameList names, double value, double minimum, double maximum,
                             std::string_view shown) const {
  if (!std::isfinite(value) || value < minimum || value > maximum) {
    fail_at(names, "must be between " + shown_number(minimum) + " and " + shown_number(maximum) + " (got " +
                       std::string(shown) + ")");
  }
  return value;
}

int OptionReader::integer_at(NameList names, int fallback, int minimum, int maximum) const {
  const int value = section_.read_int(present(names), fallback);
  if (value < minimum || value > maximum) {
    fail_at(names, "must be between " + std::to_string(minimum) + " and " + std::to_string(maximum) + " (got " +
                       std::to_string(value) + ")");
  }
  return value;
}

double OptionReader::number_at(NameList names, double fallback, double minimum, double maximum) const {
  const double value = section_.read_float(present(names), fallback);
  return checked(names, value, minimum, maximum, shown_number(value));
}

double OptionReader::length_at(NameList names, double fallback, double minimum, double maximum) const {
  const double value = section_.read_length(present(names), fallback);
  return checked(names, value, minimum, maximum, shown_number(value) + " m");
}

double OptionReader::angle_at(NameList names, double fallback, double minimum, double maximum) const {
  const double value = section_.read_angle(present(names), fallback);
  return checked(names, value, minimum, maximum, shown_number(value) + " rad");
}

bool OptionReader::flag_at(NameList names, bool fallback) const {
  const int value = section_.read_int(present(names), fallback ? 1 : 0);
  if (value != 0 && value != 1) fail_at(names, "must be 0 or 1 (got " + std::to_string(value) + ")");
  return value == 1;
}

int OptionReader::choice_at(NameList names, int fallback, std::span<const int> allowed) const {
  const int value = section_.read_int(present(names), fallback);
  for (int candidate : allowed) {
    if (value == candidate) return value;
  }
  fail_at(names, "must be one of " + join(allowed) + " (got " + std::to_string(value) + ")");
}

double OptionReader::tuple_length_at(NameList names, std::size_t element, double fallback) const {
  const double value = section_.read_tuple_length(present(names), element, fallback);
  if (!std::isfinite(value)) fail_at(names, "must be a finite length", element);
  return value;
}

double OptionReader::tuple_angle_at(NameList names, std::size_t element, double fallback) const {
  const double value = section_.read_tuple_angle(present(names), element, fallback);
  if (!std::isfinite(value)) fail_at(names, "must be a finite angle", element);
  return value;
}

double OptionReader::tuple_number_at(NameList names, std::size_t element, double fallback) const {
  const double value = section_.read_tuple_float(present(names), element, fallback);
  if (!std::isfinite(value)) fail_at(names, "must be a finite number", element);
  return value;
}

// --- The same reads with their names written at the call.

bool OptionReader::has(Names names) const { return has_any(list(names)); }

config::SourceLocation OptionReader::where(Names names, std::size_t element) const {
  return where_at(list(names), element);
}

void OptionReader::fail(Names names, const std::string& message, std::size_t element) const {
  fail_at(list(names), message, element);
}

std::string OptionReader::text(Names names, std::string_view fallback, bool allow_empty) const {
  return text_at(list(names), fallback, allow_empty);
}

std::string OptionReader::filename(Names names, std::string_view fallback) const {
  return filename_at(list(names), fallback, false);
}

std::string OptionReader::word(Names names, std::string_view fallback,
                               std::initializer_list<std::string_view> allowed) const {
  return word_at(list(names), fallback, {allowed.begin(), allowed.size()});
}

int OptionReader::integer(Names names, int fallback, int minimum, int maximum) const {
  return integer_at(list(names), fallback, minimum, maximum);
}

double OptionReader::number(Names names, double fallback, double minimum, double maximum) const {
  return number_at(list(names), fallback, minimum, maximum);
}

double OptionReader::length(Names names, double fallback, double minimum, double maximum) const {
  return length_at(list(names), fallback, minimum, maximum);
}

double OptionReader::angle(Names names, double fallback, double minimum, double maximum) const {
  return angle_at(list(names), fallback, minimum, maximum);
}

bool OptionReader::flag(Names names, bool fallback) const { return flag_at(list(names), fallback); }

int OptionReader::choice(Names names, int fallback, std::initializer_list<int> allowed) const {
  return choice_at(list(names), fallback, {allowed.begin(), allowed.size()});
}

int OptionReader::index(Names names, int fallback) const {
  const int value = section_.read_int(present(list(names)), fallback);
  if (value < 0) fail(names, "must be a device index, 0 or more (got " + std::to_string(value) + ")");
  return value;
}

int OptionReader::network_port(Names names, int fallback) const { return integer(names, fallback, 1, 65535); }

std::size_t OptionReader::tuple_size(Names names) const { return section_.tuple_size(present(list(names))); }

double OptionReader::tuple_length(Names names, std::size_t element, double fallback) const {
  return tuple_length_at(list(names), element, fallback);
}

double OptionReader::tuple_angle(Names names, std::size_t element, double fallback) const {
  return tuple_angle_at(list(names), element, fallback);
}

}  // namespace playerkit::core
