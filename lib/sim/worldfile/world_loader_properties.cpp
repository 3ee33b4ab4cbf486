#include "sim/worldfile/world_loader_properties.hpp"

#include <charconv>
#include <cmath>
#include <limits>

#include "config/closest_name.hpp"
#include "sim/worldfile/worldfile_error.hpp"
#include "text/printable.hpp"

namespace playerkit::sim::worldfile {
namespace {

double scale_of(Quantity quantity, const Units& units) {
  switch (quantity) {
    case Quantity::length: return units.metres_per_length;
    case Quantity::angle: return units.radians_per_angle;
    case Quantity::plain: break;
  }
  return 1.0;
}

std::string quoted_property(std::string_view name) { return "\"" + text::excerpt(name) + "\""; }

}  // namespace

Units read_units(const WorldTree& tree, std::vector<std::string>& warnings) {
  Units units;
  if (const Property* length = tree.world.find("unit_length"); length != nullptr && !length->values.empty()) {
    const std::string& name = length->values.front().text;
    if (name == "m") {
      units.metres_per_length = 1.0;
    } else if (name == "cm") {
      units.metres_per_length = 0.01;
    } else if (name == "mm") {
      units.metres_per_length = 0.001;
    } else {
      warnings.push_back(located(length->where, "unit_length \"" + text::excerpt(name) +
                                                    "\" is not \"m\", \"cm\" or \"mm\": lengths stay in metres"));
    }
  }
  if (const Property* angle = tree.world.find("unit_angle"); angle != nullptr && !angle->values.empty()) {
    const std::string& name = angle->values.front().text;
    if (name == "degrees") {
      units.radians_per_angle = std::numbers::pi / 180.0;
    } else if (name == "radians") {
      units.radians_per_angle = 1.0;
    } else {
      warnings.push_back(located(angle->where, "unit_angle \"" + text::excerpt(name) +
                                                   "\" is not \"degrees\" or \"radians\": angles stay in degrees"));
    }
  }
  return units;
}

bool is_gui_property(std::string_view name) { return name.starts_with("gui_") || name == "gui"; }

PropertyReader::PropertyReader(const Entity& entity, const Units& units, std::vector<std::string>& warnings)
    : entity_(entity), units_(units), warnings_(warnings) {}

const Property* PropertyReader::take(std::string_view name) {
  asked_.emplace(name);
  return entity_.find(name);
}

bool PropertyReader::has(std::string_view name) { return take(name) != nullptr; }

void PropertyReader::skip(std::initializer_list<std::string_view> names) {
  for (const std::string_view name : names) asked_.emplace(name);
}

void PropertyReader::warn(const SourceLocation& where, const std::string& message) {
  warnings_.push_back(located(where, message));
}

double PropertyReader::number_of(const Value& value, Quantity quantity) {
  // atof: the longest leading number, 0 if there is none.
  std::string_view digits = value.text;
  while (!digits.empty() && (digits.front() == ' ' || digits.front() == '\t')) digits.remove_prefix(1);
  const bool plus = !digits.empty() && digits.front() == '+';
  if (plus) digits.remove_prefix(1);
  double parsed = 0.0;
  const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), parsed,
                                            std::chars_format::fixed);
  if (error == std::errc::result_out_of_range || !std::isfinite(parsed)) {
    throw WorldFileError(value.where, "the number " + text::excerpt(value.text) + " is out of range");
  }
  if (error != std::errc()) parsed = 0.0;
  if (error != std::errc() || end != digits.data() + digits.size()) {
    const std::string read = error != std::errc() ? "0" : std::string(digits.data(), end);
    warn(value.where, "\"" + text::excerpt(value.text) + "\" is not a number; it reads as " + read + ", as in Stage");
  }
  return parsed * scale_of(quantity, units_);
}

double PropertyReader::number(std::string_view name, double fallback, Quantity quantity) {
  const Property* property = take(name);
  if (property == nullptr || property->values.empty()) return fallback;
  return number_of(property->values.front(), quantity);
}

int PropertyReader::integer(std::string_view name, int fallback) {
  const Property* property = take(name);
  if (property == nullptr || property->values.empty()) return fallback;
  const double value = number_of(property->values.front(), Quantity::plain);
  if (std::abs(value) > std::numeric_limits<int>::max()) {
    throw WorldFileError(property->values.front().where,
                         quoted_property(name) + " must be an integer between -2147483647 and 2147483647");
  }
  return static_cast<int>(value);  // truncated, as atoi reads "2.7"
}

std::string PropertyReader::text(std::string_view name, const std::string& fallback) {
  const Property* property = take(name);
  if (property == nullptr || property->values.empty()) return fallback;
  return property->values.front().text;
}

std::vector<std::string> PropertyReader::texts(std::string_view name) {
  std::vector<std::string> all;
  if (const Property* property = take(name); property != nullptr) {
    for (const Value& value : property->values) all.push_back(value.text);
  }
  return all;
}

std::optional<std::vector<double>> PropertyReader::tuple(std::string_view name, std::initializer_list<Quantity> layout,
                                                         std::string_view shape) {
  const Property* property = take(name);
  if (property == nullptr) return std::nullopt;
  if (property->values.size() < layout.size()) {
    throw WorldFileError(property->where, quoted_property(name) + " needs " + std::to_string(layout.size()) +
                                              " values " + std::string(shape) + ", found " +
                                              std::to_string(property->values.size()));
  }
  std::vector<double> numbers;
  std::size_t index = 0;
  for (const Quantity quantity : layout) numbers.push_back(number_of(property->values[index++], quantity));
  return numbers;
}

void PropertyReader::report_unread(bool (*ignorable)(std::string_view name)) {
  std::vector<std::string_view> known(asked_.begin(), asked_.end());
  for (const Property& property : entity_.properties) {
    if (asked_.contains(property.name) || (ignorable != nullptr && ignorable(property.name))) continue;
    std::string message = "unknown property " + quoted_property(property.name) + " of a " +
                          text::excerpt(entity_.type) + ", ignored";
    if (const auto suggestion = config::closest_name(property.name, known)) {
      message += " (did you mean \"" + *suggestion + "\"?)";
    }
    warn(property.where, message);
  }
}

}  // namespace playerkit::sim::worldfile
