#include "core/option_reader.hpp"

#include <cmath>
#include <sstream>

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

}  // namespace

OptionReader::OptionReader(const config::Section& section, std::string driver_name)
    : section_(section), driver_(std::move(driver_name)) {}

std::string_view OptionReader::present(Names names) const {
  for (std::string_view name : names) {
    if (section_.has(name)) return name;
  }
  return *names.begin();
}

bool OptionReader::has(Names names) const {
  for (std::string_view name : names) {
    if (section_.has(name)) return true;
  }
  return false;
}

config::SourceLocation OptionReader::where(Names names, std::size_t element) const {
  const config::Property* property = section_.property(present(names));
  if (property == nullptr) return section_.where();
  if (element < property->values.size()) return property->values[element].where;
  return property->where;
}

void OptionReader::fail(Names names, const std::string& message, std::size_t element) const {
  throw config::ConfigError(where(names, element),
                            driver_ + ": " + std::string(present(names)) + " " + message);
}

std::string OptionReader::text(Names names, std::string_view fallback, bool allow_empty) const {
  std::string value = section_.read_string(present(names), fallback);
  if (value.empty() && !allow_empty) fail(names, "must not be empty");
  return value;
}

std::string OptionReader::filename(Names names, std::string_view fallback) const {
  std::string value = section_.read_filename(present(names), fallback);
  if (value.empty()) fail(names, "must name a file");
  return value;
}

std::string OptionReader::word(Names names, std::string_view fallback,
                               std::initializer_list<std::string_view> allowed) const {
  std::string value = section_.read_string(present(names), fallback);
  for (std::string_view candidate : allowed) {
    if (value == candidate) return value;
  }
  fail(names, "must be one of " + join(allowed) + " (got \"" + value + "\")");
}

double OptionReader::checked(Names names, double value, double minimum, double maximum,
                             std::string_view shown) const {
  if (!std::isfinite(value) || value < minimum || value > maximum) {
    fail(names, "must be between " + shown_number(minimum) + " and " + shown_number(maximum) +
                    " (got " + std::string(shown) + ")");
  }
  return value;
}

int OptionReader::integer(Names names, int fallback, int minimum, int maximum) const {
  const int value = section_.read_int(present(names), fallback);
  if (value < minimum || value > maximum) {
    fail(names, "must be between " + std::to_string(minimum) + " and " + std::to_string(maximum) +
                    " (got " + std::to_string(value) + ")");
  }
  return value;
}

double OptionReader::number(Names names, double fallback, double minimum, double maximum) const {
  const double value = section_.read_float(present(names), fallback);
  return checked(names, value, minimum, maximum, shown_number(value));
}

double OptionReader::length(Names names, double fallback, double minimum, double maximum) const {
  const double value = section_.read_length(present(names), fallback);
  return checked(names, value, minimum, maximum, shown_number(value) + " m");
}

double OptionReader::angle(Names names, double fallback, double minimum, double maximum) const {
  const double value = section_.read_angle(present(names), fallback);
  return checked(names, value, minimum, maximum, shown_number(value) + " rad");
}

bool OptionReader::flag(Names names, bool fallback) const {
  const int value = section_.read_int(present(names), fallback ? 1 : 0);
  if (value != 0 && value != 1) fail(names, "must be 0 or 1 (got " + std::to_string(value) + ")");
  return value == 1;
}

int OptionReader::choice(Names names, int fallback, std::initializer_list<int> allowed) const {
  const int value = section_.read_int(present(names), fallback);
  for (int candidate : allowed) {
    if (value == candidate) return value;
  }
  fail(names, "must be one of " + join(allowed) + " (got " + std::to_string(value) + ")");
}

int OptionReader::index(Names names, int fallback) const {
  const int value = section_.read_int(present(names), fallback);
  if (value < 0) fail(names, "must be a device index, 0 or more (got " + std::to_string(value) + ")");
  return value;
}

int OptionReader::network_port(Names names, int fallback) const {
  return integer(names, fallback, 1, 65535);
}

std::size_t OptionReader::tuple_size(Names names) const { return section_.tuple_size(present(names)); }

double OptionReader::tuple_length(Names names, std::size_t element, double fallback) const {
  const double value = section_.read_tuple_length(present(names), element, fallback);
  if (!std::isfinite(value)) fail(names, "must be a finite length", element);
  return value;
}

double OptionReader::tuple_angle(Names names, std::size_t element, double fallback) const {
  const double value = section_.read_tuple_angle(present(names), element, fallback);
  if (!std::isfinite(value)) fail(names, "must be a finite angle", element);
  return value;
}

}  // namespace playerkit::core
