#include "field_path.hpp"

#include <algorithm>
#include <charconv>
#include <optional>

namespace playerkit::tools {
namespace {

std::optional<std::size_t> array_index(const std::string& segment) {
  if (segment.empty() ||
      !std::all_of(segment.begin(), segment.end(), [](char c) { return c >= '0' && c <= '9'; })) {
    return std::nullopt;
  }
  std::size_t index = 0;
  const auto [end, error] = std::from_chars(segment.data(), segment.data() + segment.size(), index);
  if (error != std::errc() || end != segment.data() + segment.size()) return std::nullopt;
  return index;
}

void flatten_into(const nlohmann::json& value, const std::string& name, std::vector<NamedValue>& out) {
  const auto child_name = [&name](const std::string& key) { return name.empty() ? key : name + "." + key; };
  if (value.is_object()) {
    for (const auto& [key, child] : value.items()) flatten_into(child, child_name(key), out);
  } else if (value.is_array()) {
    for (std::size_t i = 0; i < value.size(); ++i) flatten_into(value[i], child_name(std::to_string(i)), out);
  } else {
    out.emplace_back(name, value);
  }
}

}  // namespace

FieldPath FieldPath::parse(std::string_view text) {
  if (text.empty()) throw FieldPathError("empty field path");
  FieldPath path;
  path.text_ = std::string(text);
  std::size_t start = 0;
  for (;;) {
    const auto dot = text.find('.', start);
    const auto segment =
        text.substr(start, dot == std::string_view::npos ? std::string_view::npos : dot - start);
    if (segment.empty()) {
      throw FieldPathError("field path '" + std::string(text) + "' has an empty part (write a.b.0)");
    }
    path.segments_.emplace_back(segment);
    if (dot == std::string_view::npos) break;
    start = dot + 1;
  }
  return path;
}

const nlohmann::json* FieldPath::find_in(const nlohmann::json& data) const {
  const nlohmann::json* here = &data;
  for (const auto& segment : segments_) {
    if (here->is_object()) {
      const auto it = here->find(segment);
      if (it == here->end()) return nullptr;
      here = &*it;
    } else if (here->is_array()) {
      const auto index = array_index(segment);
      if (!index || *index >= here->size()) return nullptr;
      here = &(*here)[*index];
    } else {
      return nullptr;
    }
  }
  return here;
}

std::vector<NamedValue> flatten(const nlohmann::json& value, const std::string& prefix) {
  std::vector<NamedValue> out;
  flatten_into(value, prefix, out);
  return out;
}

std::vector<NamedValue> select_fields(const nlohmann::json& data, const std::vector<FieldPath>& fields) {
  std::vector<NamedValue> out;
  out.reserve(fields.size());
  for (const auto& field : fields) {
    const auto* value = field.find_in(data);
    out.emplace_back(field.text(), value ? *value : nlohmann::json());
  }
  return out;
}

std::vector<FieldPath> missing_fields(const nlohmann::json& data, const std::vector<FieldPath>& fields) {
  std::vector<FieldPath> missing;
  for (const auto& field : fields) {
    if (!field.find_in(data)) missing.push_back(field);
  }
  return missing;
}

std::string describe_fields(const nlohmann::json& data) {
  if (!data.is_object() || data.empty()) return "(no fields)";
  std::string text;
  for (const auto& [key, value] : data.items()) {
    if (!text.empty()) text += ", ";
    text += key;
    if (value.is_array() && !value.empty()) {
      const std::string last = std::to_string(value.size() - 1);
      text += " (array of " + std::to_string(value.size()) + ": " + key + ".0 ... " + key + "." + last + ")";
    } else if (value.is_array()) {
      text += " (empty array)";
    } else if (value.is_object()) {
      text += " (object: " + key + ".<field>)";
    }
  }
  return text;
}

}  // namespace playerkit::tools
