#include "config/section.hpp"

#include <algorithm>
#include <filesystem>
#include <system_error>

#include "config/conversions.hpp"

namespace playerkit::config {
namespace {

namespace fs = std::filesystem;

std::string resolve_filename(const Value& value) {
  if (!value.text.empty() && (value.text.front() == '/' || value.text.front() == '~')) {
    return value.text;
  }
  std::error_code error;
  const fs::path directory = fs::path(value.where.file).parent_path();
  const fs::path base =
      directory.empty() ? fs::current_path(error) : fs::absolute(directory, error);
  if (error) return (directory / value.text).string();
  return (base / value.text).string();
}

}  // namespace

Section::Section(ParsedSection parsed, Units units)
    : type_(std::move(parsed.type)),
      parent_(parsed.parent),
      where_(std::move(parsed.where)),
      properties_(std::move(parsed.properties)),
      units_(units) {}

const Property* Section::property(std::string_view name) const {
  const auto named = [&](const Property& p) { return p.name == name; };
  const auto found = std::find_if(properties_.begin(), properties_.end(), named);
  return found == properties_.end() ? nullptr : &*found;
}

bool Section::has(std::string_view name) const { return property(name) != nullptr; }

std::vector<std::string> Section::property_names() const {
  std::vector<std::string> names;
  names.reserve(properties_.size());
  for (const Property& p : properties_) names.push_back(p.name);
  return names;
}

const Value* Section::read_value(std::string_view name, std::size_t index) const {
  const Property* found = property(name);
  if (found == nullptr) return nullptr;
  found->used = true;
  return index < found->values.size() ? &found->values[index] : nullptr;
}

std::string Section::read_string(std::string_view name, std::string_view fallback) const {
  return read_tuple_string(name, 0, fallback);
}

int Section::read_int(std::string_view name, int fallback) const {
  return read_tuple_int(name, 0, fallback);
}

double Section::read_float(std::string_view name, double fallback) const {
  return read_tuple_float(name, 0, fallback);
}

double Section::read_length(std::string_view name, double fallback) const {
  return read_tuple_length(name, 0, fallback);
}

double Section::read_angle(std::string_view name, double fallback) const {
  return read_tuple_angle(name, 0, fallback);
}

std::string Section::read_filename(std::string_view name, std::string_view fallback) const {
  const Value* value = read_value(name, 0);
  return value ? resolve_filename(*value) : std::string(fallback);
}

std::size_t Section::tuple_size(std::string_view name) const {
  const Property* found = property(name);
  if (found == nullptr) return 0;
  found->used = true;
  return found->values.size();
}

std::string Section::read_tuple_string(std::string_view name, std::size_t index,
                                       std::string_view fallback) const {
  const Value* value = read_value(name, index);
  return value ? value->text : std::string(fallback);
}

int Section::read_tuple_int(std::string_view name, std::size_t index, int fallback) const {
  const Value* value = read_value(name, index);
  return value ? c_atoi(value->text) : fallback;
}

double Section::read_tuple_float(std::string_view name, std::size_t index, double fallback) const {
  const Value* value = read_value(name, index);
  return value ? c_atof(value->text) : fallback;
}

double Section::read_tuple_length(std::string_view name, std::size_t index, double fallback) const {
  const Value* value = read_value(name, index);
  return value ? c_atof(value->text) * units_.length : fallback;
}

double Section::read_tuple_angle(std::string_view name, std::size_t index, double fallback) const {
  const Value* value = read_value(name, index);
  return value ? c_atof(value->text) * units_.angle : fallback;
}

}  // namespace playerkit::config
