#include "emulators/emulator_option_reader.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace playerkit::emulators {

namespace {

std::string option_list(const EmulatorKind& kind) {
  std::string text;
  for (const auto& option : kind.options) text += (text.empty() ? "" : ", ") + option.name;
  return text;
}

std::string shown(double value) {
  std::string text = std::to_string(value);
  // "0.500000" -> "0.5"
  if (text.find('.') != std::string::npos) {
    while (text.back() == '0') text.pop_back();
    if (text.back() == '.') text.pop_back();
  }
  return text;
}

bool parse_double(std::string_view text, double& value) {
  // from_chars rejects a leading '+', which people type.
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  return error == std::errc{} && end == text.data() + text.size() && std::isfinite(value);
}

}  // namespace

EmulatorOptionReader::EmulatorOptionReader(const EmulatorKind& kind, const EmulatorOptionValues& values)
    : kind_(kind), values_(values) {
  for (std::size_t i = 0; i < values_.size(); ++i) {
    const std::string& name = values_[i].first;
    bool known = false;
    for (const auto& option : kind_.options) known = known || option.name == name;
    if (!known) {
      throw std::invalid_argument(kind_.name + ": no option '" + name + "'; its options are " +
                                  option_list(kind_));
    }
    for (std::size_t j = 0; j < i; ++j) {
      if (values_[j].first == name) throw std::invalid_argument(kind_.name + ": option '" + name + "' is given twice");
    }
  }
}

const std::string* EmulatorOptionReader::value(std::string_view name) const {
  for (const auto& [key, text] : values_) {
    if (key == name) return &text;
  }
  return nullptr;
}

bool EmulatorOptionReader::has(std::string_view name) const { return value(name) != nullptr; }

void EmulatorOptionReader::fail(std::string_view name, const std::string& why) const {
  const std::string* given = value(name);
  throw std::invalid_argument(kind_.name + ": " + std::string(name) + "=" + (given ? *given : std::string()) + ": " +
                              why);
}

std::string EmulatorOptionReader::text(std::string_view name, std::string_view fallback) const {
  const std::string* given = value(name);
  return given ? *given : std::string(fallback);
}

double EmulatorOptionReader::number(std::string_view name, double fallback, double minimum, double maximum) const {
  const std::string* given = value(name);
  if (!given) return fallback;
  double result = 0.0;
  if (!parse_double(*given, result) || result < minimum || result > maximum) {
    fail(name, "expected a number from " + shown(minimum) + " to " + shown(maximum));
  }
  return result;
}

int EmulatorOptionReader::integer(std::string_view name, int fallback, int minimum, int maximum) const {
  const std::string* given = value(name);
  if (!given) return fallback;
  int result = 0;
  const auto [end, error] = std::from_chars(given->data(), given->data() + given->size(), result);
  if (error != std::errc{} || end != given->data() + given->size() || result < minimum || result > maximum) {
    fail(name, "expected a whole number from " + std::to_string(minimum) + " to " + std::to_string(maximum));
  }
  return result;
}

bool EmulatorOptionReader::flag(std::string_view name, bool fallback) const {
  const std::string* given = value(name);
  if (!given) return fallback;
  if (*given == "1" || *given == "yes" || *given == "on" || *given == "true") return true;
  if (*given == "0" || *given == "no" || *given == "off" || *given == "false") return false;
  fail(name, "expected 1 or 0 (yes/no, on/off)");
}

geometry::Pose2 EmulatorOptionReader::pose(std::string_view name, geometry::Pose2 fallback) const {
  const std::string* given = value(name);
  if (!given) return fallback;
  std::vector<double> parts;
  std::string_view rest = *given;
  while (true) {
    const std::size_t comma = rest.find(',');
    double part = 0.0;
    if (!parse_double(rest.substr(0, comma), part)) break;
    parts.push_back(part);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
    if (parts.size() > 3) break;
  }
  const bool complete = parts.size() == 3 && given->find(',') != std::string::npos &&
                        std::count(given->begin(), given->end(), ',') == 2;
  if (!complete) fail(name, "expected x,y,yaw in metres, metres and degrees, e.g. 1.5,-2,90");
  return {parts[0], parts[1], geometry::normalize_angle(parts[2] * std::numbers::pi / 180.0)};
}

}  // namespace playerkit::emulators
