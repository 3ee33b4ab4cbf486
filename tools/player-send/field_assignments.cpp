#include "field_assignments.hpp"

#include <algorithm>
#include <cctype>
#include <cstddef>
#include <string>
#include <vector>

#include "protocol/constants.hpp"
#include "usage_error.hpp"

namespace playerkit::player_send {

namespace {

// One step of a field path: a struct member or a list element.
struct PathStep {
  std::string name;  // empty for a list element
  std::size_t index = 0;

  [[nodiscard]] bool is_index() const { return name.empty(); }
  friend bool operator==(const PathStep&, const PathStep&) = default;
};

bool is_name(std::string_view text) {
  if (text.empty() || std::isdigit(static_cast<unsigned char>(text.front()))) return false;
  return std::all_of(text.begin(), text.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; });
}

bool is_digits(std::string_view text) {
  return !text.empty() &&
         std::all_of(text.begin(), text.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); });
}

std::vector<PathStep> parse_path(std::string_view path, const std::string& argument) {
  if (path.empty()) throw UsageError("'" + argument + "': the field name before '=' is missing");
  std::vector<PathStep> steps;
  std::size_t start = 0;
  for (;;) {
    const auto dot = path.find('.', start);
    const auto step = path.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start);
    if (is_digits(step)) {
      if (steps.empty()) throw UsageError("'" + argument + "': a field path starts with a field name, not a number");
      // No payload holds more elements than it has bytes: refuse before allocating.
      if (step.size() > 5 || std::stoul(std::string(step)) >= protocol::kMaxPayloadSize) {
        throw UsageError("'" + argument + "': element " + std::string(step) + " is beyond any payload (at most " +
                         std::to_string(protocol::kMaxPayloadSize - 1) + ")");
      }
      steps.push_back({"", std::stoul(std::string(step))});
    } else if (is_name(step)) {
      steps.push_back({std::string(step), 0});
    } else {
      throw UsageError("'" + argument + "': '" + std::string(step) +
                       "' is not a field name or element number (fields are written like pose.0 or id.code)");
    }
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return steps;
}

std::string path_text(std::span<const PathStep> steps) {
  std::string text;
  for (const auto& step : steps) {
    if (!text.empty()) text += '.';
    text += step.is_index() ? std::to_string(step.index) : step.name;
  }
  return text;
}

// Elements skipped over by "pose.2=5" become the zero of their siblings' kind.
void fill_gaps(nlohmann::json& value) {
  if (value.is_object()) {
    for (auto& item : value.items()) fill_gaps(item.value());
    return;
  }
  if (!value.is_array()) return;
  nlohmann::json zero = 0;
  for (const auto& element : value) {
    if (element.is_object()) zero = nlohmann::json::object();
    if (element.is_array()) zero = nlohmann::json::array();
    if (element.is_string()) zero = "";
    if (!element.is_null()) break;
  }
  for (auto& element : value) {
    if (element.is_null()) element = zero;
    fill_gaps(element);
  }
}

}  // namespace

nlohmann::json parse_value(std::string_view text) {
  auto value = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (value.is_discarded()) return std::string(text);
  return value;
}

nlohmann::json parse_field_assignments(std::span<const std::string> assignments) {
  nlohmann::json fields = nlohmann::json::object();
  std::vector<std::vector<PathStep>> given;
  for (const auto& argument : assignments) {
    const auto equals = argument.find('=');
    if (equals == std::string::npos) {
      throw UsageError("'" + argument + "': expected FIELD=VALUE (like xspeed=200 or pose.0=100)");
    }
    const auto steps = parse_path(std::string_view(argument).substr(0, equals), argument);
    for (const auto& earlier : given) {
      const auto common = std::min(earlier.size(), steps.size());
      if (std::equal(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(common), earlier.begin())) {
        throw UsageError("'" + argument + "': " + path_text(std::span(steps).first(common)) +
                         " is given more than once");
      }
    }
    given.push_back(steps);

    nlohmann::json* node = &fields;
    for (std::size_t i = 0; i < steps.size(); ++i) {
      const auto& step = steps[i];
      const std::string where = path_text(std::span(steps).first(i));
      if (step.is_index()) {
        if (node->is_null()) *node = nlohmann::json::array();
        if (!node->is_array()) {
          throw UsageError("'" + argument + "': " + where + " is given as a struct elsewhere, here as a list");
        }
        while (node->size() <= step.index) node->push_back(nullptr);
        node = &(*node)[step.index];
      } else {
        if (node->is_null()) *node = nlohmann::json::object();
        if (!node->is_object()) {
          throw UsageError("'" + argument + "': " + where + " is given as a list elsewhere, here as a struct");
        }
        node = &(*node)[step.name];
      }
    }
    *node = parse_value(std::string_view(argument).substr(equals + 1));
  }
  fill_gaps(fields);
  return fields;
}

}  // namespace playerkit::player_send
