#pragma once
// Generic conversion between WireStructs and JSON, using the spec's field names.
//
//   nlohmann::json j = to_json(scan);           // {"min_angle": -9000, ..., "ranges": [...]}
//   LaserData scan = from_json<LaserData>(j);   // throws JsonError naming the field
//
// Rules, the same for every struct:
//  * values are in wire units (mm, 0.01 deg, ...), exactly as on the wire;
//  * counted arrays show only their `count` elements; when parsing, a missing count
//    is taken from the array's length;
//  * text fields are strings up to their first NUL (what follows a NUL is padding);
//    bytes above 0x7F map to U+0080..U+00FF so any text survives a round trip;
//  * fields missing from the JSON are zero; unknown fields are an error.

#include <algorithm>
#include <cstdint>
#include <limits>
#include <set>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

#include "protocol/errors.hpp"
#include "protocol/fields.hpp"

namespace playerkit::protocol {

namespace detail {

std::string latin1_to_utf8(std::string_view bytes);
// Throws JsonError(path ...) for characters above U+00FF or malformed UTF-8.
std::string utf8_to_latin1(std::string_view text, const std::string& path);
std::int64_t json_integer(const nlohmann::json& j, const std::string& path, std::int64_t min,
                          std::uint64_t max);
[[noreturn]] void throw_json_type(const std::string& path, std::string_view wanted,
                                  const nlohmann::json& got);

template <class V>
nlohmann::json value_to_json(const V& value);

template <WireStruct T>
nlohmann::json struct_to_json(const T& value) {
  nlohmann::json out = nlohmann::json::object();
  for_each_field<T>([&](const auto& d) {
    using D = std::remove_cvref_t<decltype(d)>;
    const auto& member = value.*(d.member);
    if constexpr (is_counted_field_v<D>) {
      const auto count = std::min<std::size_t>(static_cast<std::size_t>(value.*(d.count)), member.size());
      nlohmann::json array = nlohmann::json::array();
      for (std::size_t i = 0; i < count; ++i) array.push_back(value_to_json(member[i]));
      out[std::string(d.name)] = std::move(array);
    } else if constexpr (is_tail_field_v<D>) {
      nlohmann::json array = nlohmann::json::array();
      for (const auto& element : member) array.push_back(value_to_json(element));
      out[std::string(d.name)] = std::move(array);
    } else {
      out[std::string(d.name)] = value_to_json(member);
    }
  });
  return out;
}

template <class V>
nlohmann::json value_to_json(const V& value) {
  if constexpr (std::is_integral_v<V>) {
    return value;
  } else if constexpr (is_std_array_v<V>) {
    nlohmann::json array = nlohmann::json::array();
    for (const auto& element : value) array.push_back(value_to_json(element));
    return array;
  } else if constexpr (is_fixed_string_v<V>) {
    return latin1_to_utf8(value.view());
  } else {
    return struct_to_json(value);
  }
}

template <class V>
void value_from_json(const nlohmann::json& j, V& out, const std::string& path);

template <class Element>
std::size_t array_from_json(const nlohmann::json& j, Element* elements, std::size_t capacity,
                            const std::string& path) {
  if (!j.is_array()) throw_json_type(path, "an array", j);
  if (j.size() > capacity) {
    throw JsonError(path + ": " + std::to_string(j.size()) + " elements, at most " +
                    std::to_string(capacity) + " fit");
  }
  for (std::size_t i = 0; i < j.size(); ++i) {
    value_from_json(j[i], elements[i], path + "[" + std::to_string(i) + "]");
  }
  return j.size();
}

// The name of the plain field of T stored at `member`.
template <WireStruct T, class M>
std::string_view field_name_of(M T::*member) {
  std::string_view name;
  for_each_field<T>([&](const auto& d) {
    using D = std::remove_cvref_t<decltype(d)>;
    if constexpr (!is_counted_field_v<D> && !is_tail_field_v<D>) {
      if constexpr (std::is_same_v<decltype(d.member), M T::*>) {
        if (d.member == member) name = d.name;
      }
    }
  });
  return name;
}

template <WireStruct T>
void struct_from_json(const nlohmann::json& j, T& out, const std::string& path) {
  if (!j.is_object()) throw_json_type(path, "an object", j);
  std::set<std::string, std::less<>> known;
  for_each_field<T>([&](const auto& d) { known.emplace(d.name); });
  for (const auto& item : j.items()) {
    if (!known.contains(item.key())) {
      std::string names;
      for (const auto& k : known) names += (names.empty() ? "" : ", ") + k;
      throw JsonError(path + ": unknown field '" + item.key() + "' (fields: " + names + ")");
    }
  }
  for_each_field<T>([&](const auto& d) {
    using D = std::remove_cvref_t<decltype(d)>;
    const std::string key(d.name);
    const auto it = j.find(key);
    if (it == j.end()) return;
    auto& member = out.*(d.member);
    const std::string field_path = path + "." + key;
    if constexpr (is_counted_field_v<D>) {
      array_from_json(*it, member.data(), member.size(), field_path);
    } else if constexpr (is_tail_field_v<D>) {
      if (!it->is_array()) throw_json_type(field_path, "an array", *it);
      member.resize(std::min<std::size_t>(it->size(), d.max_count));
      array_from_json(*it, member.data(), d.max_count, field_path);
    } else {
      value_from_json(*it, member, field_path);
    }
  });
  // A count left out of the JSON follows the length of the array it counts.
  for_each_field<T>([&](const auto& d) {
    using D = std::remove_cvref_t<decltype(d)>;
    if constexpr (is_counted_field_v<D> || is_tail_field_v<D>) {
      const auto array = j.find(std::string(d.name));
      if (array == j.end() || d.count == nullptr) return;
      if (!j.contains(std::string(field_name_of<T>(d.count)))) {
        using Count = std::remove_cvref_t<decltype(out.*(d.count))>;
        out.*(d.count) = static_cast<Count>(array->size());
      }
    }
  });
}

template <class V>
void value_from_json(const nlohmann::json& j, V& out, const std::string& path) {
  if constexpr (std::is_integral_v<V>) {
    out = static_cast<V>(json_integer(j, path, std::numeric_limits<V>::min(),
                                      static_cast<std::uint64_t>(std::numeric_limits<V>::max())));
  } else if constexpr (is_std_array_v<V>) {
    array_from_json(j, out.data(), out.size(), path);
  } else if constexpr (is_fixed_string_v<V>) {
    if (!j.is_string()) throw_json_type(path, "a string", j);
    const std::string bytes = utf8_to_latin1(j.get_ref<const std::string&>(), path);
    if (bytes.size() > V::kCapacity) {
      throw JsonError(path + ": text of " + std::to_string(bytes.size()) +
                      " characters does not fit (at most " + std::to_string(V::kCapacity) + ")");
    }
    // Filling the whole field leaves no NUL, exactly as a decoded full field was.
    out.bytes.fill('\0');
    std::copy(bytes.begin(), bytes.end(), out.bytes.begin());
  } else {
    struct_from_json(j, out, path);
  }
}

}  // namespace detail

template <WireStruct T>
nlohmann::json to_json(const T& value) {
  return detail::struct_to_json(value);
}

template <WireStruct T>
T from_json(const nlohmann::json& j) {
  T value{};
  detail::struct_from_json(j, value, std::string(T::kWireName));
  return value;
}

}  // namespace playerkit::protocol
