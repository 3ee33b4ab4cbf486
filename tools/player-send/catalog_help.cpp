#include "catalog_help.hpp"

#include <algorithm>
#include <cstdint>
#include <exception>
#include <map>
#include <optional>
#include <sstream>

#include "protocol/interfaces.hpp"

namespace playerkit::player_send {

namespace {

// Wider structs (camera images) are not decoded at full size just for --help.
constexpr std::size_t kLargestProbe = 64 * 1024;

std::optional<nlohmann::json> zero_struct_json(const protocol::PayloadCodec& codec, std::size_t size) {
  try {
    return codec.to_json(std::vector<std::uint8_t>(size, 0));
  } catch (const std::exception&) {
    return std::nullopt;
  }
}

// Which top-level field holds the leading subtype bytes: the one that changes
// when those bytes do.
std::optional<std::string> subtype_field(const protocol::PayloadCodec& codec, const nlohmann::json& zero,
                                         std::size_t subtype_size) {
  if (subtype_size == 0 || codec.min_size < subtype_size) return std::nullopt;
  std::vector<std::uint8_t> bytes(codec.min_size, 0);
  for (std::size_t i = 0; i < subtype_size; ++i) bytes[i] = 1;
  try {
    const auto marked = codec.to_json(bytes);
    for (const auto& item : zero.items()) {
      if (marked.contains(item.key()) && marked.at(item.key()) != item.value()) return item.key();
    }
  } catch (const std::exception&) {
  }
  return std::nullopt;
}

// A field as --help shows it, with the path that orders it.
struct ListedField {
  std::string path;  // "id.code", "pose"
  std::string text;  // "id.code", "pose[3]", "channel (text)"
};

std::string list_shape(const nlohmann::json& at_min, const nlohmann::json* at_max) {
  const bool fixed = !at_min.empty() && (!at_max || at_max->size() == at_min.size());
  std::string text = "[";
  if (fixed) text += std::to_string(at_min.size());
  text += "]";
  if (at_min.empty()) return text;
  const auto& element = at_min.front();
  if (element.is_array()) return text + list_shape(element, nullptr);
  if (element.is_object()) {
    std::string members;
    for (const auto& item : element.items()) members += (members.empty() ? "" : ",") + item.key();
    text += ".{" + members + "}";
  }
  return text;
}

void list_fields(const std::string& path, const nlohmann::json& at_min, const nlohmann::json* at_max,
                 std::vector<ListedField>& out) {
  if (at_min.is_object()) {
    for (const auto& item : at_min.items()) {
      const nlohmann::json* max_value =
          at_max && at_max->is_object() && at_max->contains(item.key()) ? &at_max->at(item.key()) : nullptr;
      list_fields(path.empty() ? item.key() : path + "." + item.key(), item.value(), max_value, out);
    }
  } else if (at_min.is_array()) {
    out.push_back({path, path + list_shape(at_min, at_max && at_max->is_array() ? at_max : nullptr)});
  } else if (at_min.is_string()) {
    out.push_back({path, path + " (text)"});
  } else {
    out.push_back({path, path});
  }
}

// Leaves (scalars and whole lists) by path, to see which one a byte belongs to.
void flatten(const std::string& path, const nlohmann::json& value, std::map<std::string, nlohmann::json>& out) {
  if (value.is_object()) {
    for (const auto& item : value.items()) flatten(path.empty() ? item.key() : path + "." + item.key(), item.value(), out);
  } else {
    out[path] = value;
  }
}

// The codecs' JSON is ordered by name; the wire order (xpos ypos yaw ...) is
// the manual's. It is found by marking one byte at a time and seeing which
// field changes. Fields never seen (and structs too large to probe) keep
// their place after the others.
std::map<std::string, std::size_t> wire_offsets(const protocol::PayloadCodec& codec, const nlohmann::json& zero) {
  constexpr std::size_t kLargestOrdered = 8192;
  std::map<std::string, std::size_t> offsets;
  if (codec.min_size > kLargestOrdered) return offsets;
  std::map<std::string, nlohmann::json> zero_leaves;
  flatten("", zero, zero_leaves);
  std::vector<std::uint8_t> bytes(codec.min_size, 0);
  for (std::size_t offset = 0; offset < bytes.size() && offsets.size() < zero_leaves.size(); ++offset) {
    bytes[offset] = 1;
    try {
      std::map<std::string, nlohmann::json> leaves;
      flatten("", codec.to_json(bytes), leaves);
      for (const auto& [path, value] : leaves) {
        const auto before = zero_leaves.find(path);
        if (before != zero_leaves.end() && before->second != value) offsets.emplace(path, offset);
      }
    } catch (const std::exception&) {
      // A marked count larger than its list: that byte names no field of its own.
    }
    bytes[offset] = 0;
  }
  return offsets;
}

std::string joined(const std::vector<std::string>& words) {
  std::string text;
  for (const auto& word : words) text += (text.empty() ? "" : " ") + word;
  return text;
}

// Long field lists continue on lines indented under the first.
void append_wrapped(std::ostringstream& out, const std::string& lead, const std::vector<std::string>& words) {
  constexpr std::size_t kWidth = 100;
  const std::string indent(8, ' ');
  std::string line = lead;
  for (const auto& word : words) {
    if (line.size() + 1 + word.size() > kWidth && line.size() > indent.size()) {
      out << line << "\n";
      line = indent;
    } else if (!line.empty() && line.back() != ' ') {
      line += ' ';
    }
    line += word;
  }
  out << line << "\n";
}

}  // namespace

std::vector<std::string> settable_fields(const protocol::PayloadCodec& codec, std::size_t subtype_size) {
  const auto at_min = zero_struct_json(codec, codec.min_size);
  if (!at_min || !at_min->is_object()) return {};
  std::optional<nlohmann::json> at_max;
  if (codec.max_size != codec.min_size && codec.max_size <= kLargestProbe) {
    at_max = zero_struct_json(codec, codec.max_size);
  }
  nlohmann::json fields = *at_min;
  if (const auto subtype = subtype_field(codec, *at_min, subtype_size)) {
    fields.erase(*subtype);
    if (at_max && at_max->is_object()) at_max->erase(*subtype);
  }
  std::vector<ListedField> listed;
  list_fields("", fields, at_max ? &*at_max : nullptr, listed);
  const auto offsets = wire_offsets(codec, *at_min);
  const auto offset_of = [&](const ListedField& field) {
    const auto it = offsets.find(field.path);
    return it == offsets.end() ? codec.min_size : it->second;
  };
  std::stable_sort(listed.begin(), listed.end(),
                   [&](const ListedField& a, const ListedField& b) { return offset_of(a) < offset_of(b); });
  std::vector<std::string> out;
  for (auto& field : listed) out.push_back(std::move(field.text));
  return out;
}

std::string interface_help(const protocol::InterfaceMessages& messages) {
  if (!messages.command && messages.requests.empty()) return "";
  std::ostringstream out;
  out << protocol::interface_name(messages.interface) << "\n";
  if (messages.command) append_wrapped(out, "  cmd: ", settable_fields(*messages.command));
  for (const auto& kind : messages.requests) {
    std::string lead = "  req " + std::string(kind.name) + ": " + std::string(kind.summary);
    std::vector<std::string> fields;
    if (kind.form == protocol::RequestForm::kStruct && kind.request) {
      fields = settable_fields(*kind.request, messages.subtype_size);
    }
    if (fields.empty()) {
      out << lead << " (no fields)\n";
    } else {
      append_wrapped(out, lead + "; fields: ", fields);
    }
  }
  return out.str();
}

std::string catalog_help() {
  std::ostringstream out;
  std::vector<std::string> nothing_to_send;
  for (const auto& messages : protocol::all_messages()) {
    const auto text = interface_help(messages);
    if (text.empty()) {
      nothing_to_send.push_back(protocol::interface_name(messages.interface));
    } else {
      out << text;
    }
  }
  if (!nothing_to_send.empty()) {
    out << "Nothing to send (data only): " << joined(nothing_to_send) << "\n";
  }
  return out.str();
}

}  // namespace playerkit::player_send
