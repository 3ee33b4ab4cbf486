#include "core/option_schema.hpp"

#include <climits>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <utility>

namespace playerkit::core {

namespace {

std::string shown_number(double value) {
  std::ostringstream out;
  out << value;
  return out.str();
}

double degrees(double radians) { return radians * 180.0 / std::numbers::pi; }

// "a, b or c".
std::string either(const std::vector<std::string>& items) {
  std::string text;
  for (std::size_t i = 0; i < items.size(); ++i) {
    if (i > 0) text += i + 1 == items.size() ? " or " : ", ";
    text += items[i];
  }
  return text;
}

// Limits that stand for "no limit" are not worth a line of documentation.
bool unbounded_below(double minimum) { return minimum <= std::numeric_limits<int>::min() || std::isinf(minimum) || minimum <= -std::numeric_limits<double>::max(); }
bool unbounded_above(double maximum) { return maximum >= std::numeric_limits<int>::max() || std::isinf(maximum) || maximum >= std::numeric_limits<double>::max(); }

std::string range_text(double minimum, double maximum, std::string (*shown)(double)) {
  const bool low = !unbounded_below(minimum);
  const bool high = !unbounded_above(maximum);
  if (low && high) return shown(minimum) + " to " + shown(maximum);
  if (low) return shown(minimum) + " or more";
  if (high) return "at most " + shown(maximum);
  return "";
}

std::string shown_degrees(double radians) { return shown_number(degrees(radians)); }

std::string element_text(OptionType type) {
  switch (type) {
    case OptionType::length: return "length";
    case OptionType::angle: return "angle";
    default: return "float";
  }
}

std::string markdown_cell(std::string text) {
  std::string escaped;
  for (const char c : text) {
    if (c == '|') escaped += '\\';
    escaped += c;
  }
  return escaped;
}

}  // namespace

OptionSpec::OptionSpec(std::string name, OptionType type) : name_(std::move(name)), type_(type) {}

OptionSpec OptionSpec::number(std::string name, double fallback, double minimum, double maximum) {
  OptionSpec spec(std::move(name), OptionType::number);
  spec.number_fallback_ = fallback;
  spec.minimum_ = minimum;
  spec.maximum_ = maximum;
  return spec;
}

OptionSpec OptionSpec::integer(std::string name, int fallback, int minimum, int maximum) {
  OptionSpec spec = number(std::move(name), fallback, minimum, maximum);
  spec.type_ = OptionType::integer;
  return spec;
}

OptionSpec OptionSpec::length(std::string name, double fallback_metres, double minimum, double maximum) {
  OptionSpec spec = number(std::move(name), fallback_metres, minimum, maximum);
  spec.type_ = OptionType::length;
  spec.unit_ = "m";
  return spec;
}

OptionSpec OptionSpec::angle(std::string name, double fallback_radians, double minimum, double maximum) {
  OptionSpec spec = number(std::move(name), fallback_radians, minimum, maximum);
  spec.type_ = OptionType::angle;
  spec.unit_ = "deg";
  return spec;
}

OptionSpec OptionSpec::flag(std::string name, bool fallback) {
  OptionSpec spec(std::move(name), OptionType::flag);
  spec.number_fallback_ = fallback ? 1 : 0;
  spec.minimum_ = 0;
  spec.maximum_ = 1;
  return spec;
}

OptionSpec OptionSpec::text(std::string name, std::string fallback) {
  OptionSpec spec(std::move(name), OptionType::text);
  spec.text_fallback_ = std::move(fallback);
  return spec;
}

OptionSpec OptionSpec::filename(std::string name, std::string fallback) {
  OptionSpec spec = text(std::move(name), std::move(fallback));
  spec.type_ = OptionType::filename;
  return spec;
}

OptionSpec OptionSpec::word(std::string name, std::string fallback, std::vector<std::string> words) {
  OptionSpec spec = text(std::move(name), std::move(fallback));
  spec.type_ = OptionType::word;
  spec.words_ = std::move(words);
  return spec;
}

OptionSpec OptionSpec::choice(std::string name, int fallback, std::vector<int> choices) {
  OptionSpec spec(std::move(name), OptionType::choice);
  spec.number_fallback_ = fallback;
  spec.choices_ = std::move(choices);
  return spec;
}

OptionSpec OptionSpec::tuple(std::string name, std::vector<OptionType> elements, std::vector<double> fallback) {
  if (elements.size() != fallback.size()) {
    throw std::logic_error("option " + name + ": one fallback per tuple element");
  }
  for (const OptionType element : elements) {
    if (element != OptionType::number && element != OptionType::length && element != OptionType::angle) {
      throw std::logic_error("option " + name + ": tuple elements are numbers, lengths or angles");
    }
  }
  OptionSpec spec(std::move(name), OptionType::tuple);
  spec.elements_ = std::move(elements);
  spec.tuple_fallback_ = std::move(fallback);
  return spec;
}

OptionSpec OptionSpec::link_port(std::string name, std::string fallback, TextCheck check) {
  OptionSpec spec = text(std::move(name), std::move(fallback));
  spec.type_ = OptionType::link_port;
  spec.check_ = std::move(check);
  return spec;
}

OptionSpec&& OptionSpec::unit(std::string unit) && {
  unit_ = std::move(unit);
  return std::move(*this);
}

OptionSpec&& OptionSpec::doc(std::string doc) && {
  doc_ = std::move(doc);
  return std::move(*this);
}

OptionSpec&& OptionSpec::aliases(std::vector<std::string> older_names) && {
  aliases_ = std::move(older_names);
  return std::move(*this);
}

OptionSpec&& OptionSpec::shown_default(std::string text) && {
  shown_default_ = std::move(text);
  return std::move(*this);
}

OptionSpec&& OptionSpec::allow_empty() && {
  allow_empty_ = true;
  return std::move(*this);
}

OptionSpec&& OptionSpec::check(TextCheck check) && {
  check_ = std::move(check);
  return std::move(*this);
}

std::vector<std::string_view> OptionSpec::names() const {
  std::vector<std::string_view> names{name_};
  names.insert(names.end(), aliases_.begin(), aliases_.end());
  return names;
}

std::string OptionSpec::default_text() const {
  if (!shown_default_.empty()) return shown_default_;
  switch (type_) {
    case OptionType::integer:
    case OptionType::choice:
    case OptionType::flag: return std::to_string(static_cast<int>(number_fallback_));
    case OptionType::number:
    case OptionType::length: return shown_number(number_fallback_);
    case OptionType::angle: return shown_degrees(number_fallback_);
    case OptionType::text:
    case OptionType::filename:
    case OptionType::word:
    case OptionType::link_port: return "\"" + text_fallback_ + "\"";
    case OptionType::tuple: {
      std::string text = "[";
      for (std::size_t i = 0; i < elements_.size(); ++i) {
        if (i > 0) text += ' ';
        text += elements_[i] == OptionType::angle ? shown_degrees(tuple_fallback_[i]) : shown_number(tuple_fallback_[i]);
      }
      return text + "]";
    }
  }
  return "";
}

std::string OptionSpec::allowed_text() const {
  switch (type_) {
    case OptionType::integer:
    case OptionType::number:
    case OptionType::length: return range_text(minimum_, maximum_, shown_number);
    case OptionType::angle: return range_text(minimum_, maximum_, shown_degrees);
    case OptionType::flag: return "0 or 1";
    case OptionType::choice: {
      std::vector<std::string> shown;
      for (const int choice : choices_) shown.push_back(std::to_string(choice));
      return either(shown);
    }
    case OptionType::word: return either(words_);
    // Its type, "port", and its doc say it: a tty path or tcp:HOST:PORT.
    case OptionType::link_port:
    case OptionType::text:
    case OptionType::filename:
    case OptionType::tuple: return "";
  }
  return "";
}

std::string OptionSpec::type_text() const {
  switch (type_) {
    case OptionType::integer:
    case OptionType::choice:
    case OptionType::flag: return "int";
    case OptionType::number: return "float";
    case OptionType::length: return "length";
    case OptionType::angle: return "angle";
    case OptionType::text:
    case OptionType::word: return "string";
    case OptionType::filename: return "filename";
    case OptionType::link_port: return "port";
    case OptionType::tuple: {
      std::string text = "[";
      for (std::size_t i = 0; i < elements_.size(); ++i) text += (i > 0 ? " " : "") + element_text(elements_[i]);
      return text + "]";
    }
  }
  return "";
}

OptionSchema::OptionSchema(std::initializer_list<OptionSpec> options) {
  for (const OptionSpec& option : options) add(option);
}

void OptionSchema::add(OptionSpec option) {
  for (const std::string_view name : option.names()) {
    if (find(name) != nullptr) throw std::logic_error("option " + std::string(name) + " is declared twice");
  }
  options_.push_back(std::move(option));
}

void OptionSchema::add(const OptionSchema& other) {
  for (const OptionSpec& option : other.options()) add(option);
}

const OptionSpec* OptionSchema::find(std::string_view name) const {
  for (const OptionSpec& option : options_) {
    for (const std::string_view candidate : option.names()) {
      if (candidate == name) return &option;
    }
  }
  return nullptr;
}

std::vector<OptionDoc> OptionSchema::docs() const {
  std::vector<OptionDoc> rows;
  rows.reserve(options_.size());
  for (const OptionSpec& option : options_) {
    std::string name = option.name();
    for (const std::string& alias : option.aliases()) name += "/" + alias;
    std::string summary = option.doc();
    if (const std::string allowed = option.allowed_text(); !allowed.empty()) {
      summary += (summary.empty() ? "" : "; ") + allowed;
    }
    rows.push_back({std::move(name), option.type_text(), option.default_text(), option.unit(), std::move(summary)});
  }
  return rows;
}

std::string OptionSchema::markdown() const {
  std::string table = "| option | type | default | unit | values | what |\n|---|---|---|---|---|---|\n";
  for (const OptionSpec& option : options_) {
    std::string name = "`" + option.name() + "`";
    for (const std::string& alias : option.aliases()) name += " (or `" + alias + "`)";
    table += "| " + name + " | " + markdown_cell(option.type_text()) + " | `" + markdown_cell(option.default_text()) +
             "` | " + markdown_cell(option.unit()) + " | " + markdown_cell(option.allowed_text()) + " | " +
             markdown_cell(option.doc()) + " |\n";
  }
  return table;
}

}  // namespace playerkit::core
