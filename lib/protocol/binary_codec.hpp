#pragma once
// Generic big-endian encoder and decoder for every WireStruct.
//
//   std::vector<std::uint8_t> bytes = encode(scan);
//   LaserData back = decode<LaserData>(bytes);      // throws DecodeError
//
// Decoding checks the payload length against the struct (including the short
// forms of wire-format.md §6) before reading anything, and validates counts, so a
// decoded value never claims more elements than it holds.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "protocol/byte_order.hpp"
#include "protocol/errors.hpp"
#include "protocol/fields.hpp"
#include "protocol/layout.hpp"

namespace playerkit::protocol {

namespace detail {

template <class V>
void write_value(std::uint8_t*& out, const V& value) {
  if constexpr (std::is_integral_v<V>) {
    store_be(out, value);
    out += sizeof(V);
  } else if constexpr (is_std_array_v<V>) {
    for (const auto& element : value) write_value(out, element);
  } else if constexpr (is_fixed_string_v<V>) {
    for (char c : value.bytes) *out++ = static_cast<std::uint8_t>(c);
  } else {
    static_assert(WireStruct<V>);
    for_each_field<V>([&](const auto& d) {
      static_assert(!is_tail_field_v<std::remove_cvref_t<decltype(d)>>,
                    "nested structs have a fixed size");
      write_value(out, value.*(d.member));
    });
  }
}

template <class V>
void read_value(const std::uint8_t*& in, V& value) {
  if constexpr (std::is_integral_v<V>) {
    value = load_be<V>(in);
    in += sizeof(V);
  } else if constexpr (is_std_array_v<V>) {
    for (auto& element : value) read_value(in, element);
  } else if constexpr (is_fixed_string_v<V>) {
    for (char& c : value.bytes) c = static_cast<char>(*in++);
  } else {
    static_assert(WireStruct<V>);
    for_each_field<V>([&](const auto& d) { read_value(in, value.*(d.member)); });
  }
}

// A count field that disagrees with the elements it counts: larger than its
// array, or (for sized tails) different from the tail's length.
struct CountProblem {
  std::string field;  // path below the top struct: "poses.pose_count" style, e.g. "msg.bytes"
  std::size_t count = 0;
  std::size_t capacity = 0;
  bool must_equal = false;
};

// Whether V holds a struct with fields of its own to check (nothing to walk for
// plain integers and text, which keeps the check cheap on hot decode paths).
template <class V>
constexpr bool holds_structs() {
  if constexpr (is_std_array_v<V>) {
    return holds_structs<typename V::value_type>();
  } else {
    return WireStruct<V>;
  }
}

inline std::string join_path(const std::string& prefix, std::string_view name) {
  return prefix.empty() ? std::string(name) : prefix + "." + std::string(name);
}

template <class V>
std::optional<CountProblem> find_count_problem(const V& value, const std::string& prefix);

template <class E>
std::optional<CountProblem> find_in_elements(const E* elements, std::size_t n, const std::string& path) {
  if constexpr (holds_structs<E>()) {
    for (std::size_t i = 0; i < n; ++i) {
      if (auto p = find_count_problem(elements[i], path + "[" + std::to_string(i) + "]")) return p;
    }
  } else {
    (void)elements;
    (void)n;
    (void)path;
  }
  return std::nullopt;
}

template <class V>
std::optional<CountProblem> find_count_problem(const V& value, const std::string& prefix) {
  if constexpr (is_std_array_v<V>) {
    return find_in_elements(value.data(), value.size(), prefix);
  } else if constexpr (WireStruct<V>) {
    std::optional<CountProblem> problem;
    for_each_field<V>([&](const auto& d) {
      if (problem) return;
      using D = std::remove_cvref_t<decltype(d)>;
      const auto& member = value.*(d.member);
      using Member = std::remove_cvref_t<decltype(member)>;
      if constexpr (is_counted_field_v<D>) {
        const auto count = static_cast<std::size_t>(value.*(d.count));
        if (count > member.size()) {
          problem = CountProblem{join_path(prefix, d.name), count, member.size(), false};
        } else if constexpr (holds_structs<typename Member::value_type>()) {
          problem = find_in_elements(member.data(), count, join_path(prefix, d.name));
        }
      } else if constexpr (is_tail_field_v<D>) {
        if (d.count != nullptr && static_cast<std::size_t>(value.*(d.count)) != member.size()) {
          problem = CountProblem{join_path(prefix, d.name), static_cast<std::size_t>(value.*(d.count)),
                                 member.size(), true};
        } else if constexpr (holds_structs<typename Member::value_type>()) {
          problem = find_in_elements(member.data(), member.size(), join_path(prefix, d.name));
        }
      } else if constexpr (holds_structs<Member>()) {
        problem = find_count_problem(member, join_path(prefix, d.name));
      }
    });
    return problem;
  } else {
    (void)value;
    (void)prefix;
    return std::nullopt;
  }
}

template <WireStruct T, class D>
std::size_t encoded_field_size(const T& value, const D& d) {
  if constexpr (is_counted_field_v<D>) {
    using Element = typename std::remove_cvref_t<decltype(value.*(d.member))>::value_type;
    constexpr std::size_t capacity = std::tuple_size_v<std::remove_cvref_t<decltype(value.*(d.member))>>;
    if (!d.wire_carries_count_only) return capacity * wire_size_of<Element>();
    const auto count = static_cast<std::size_t>(value.*(d.count));
    if (count > capacity) {
      throw EncodeError(std::string(T::kWireName) + ": field '" + std::string(d.name) +
                        "': count " + std::to_string(count) + " exceeds its " +
                        std::to_string(capacity) + " elements");
    }
    return count * wire_size_of<Element>();
  } else if constexpr (is_tail_field_v<D>) {
    using Element = typename std::remove_cvref_t<decltype(value.*(d.member))>::value_type;
    const std::size_t count = (value.*(d.member)).size();
    if (count > d.max_count) {
      throw EncodeError(std::string(T::kWireName) + ": field '" + std::string(d.name) + "' has " +
                        std::to_string(count) + " elements, at most " +
                        std::to_string(d.max_count) + " fit");
    }
    return count * wire_size_of<Element>();
  } else {
    return field_bytes(d).nominal;
  }
}

}  // namespace detail

// Exact number of bytes encode(value) produces.
template <WireStruct T>
std::size_t encoded_size(const T& value) {
  std::size_t total = 0;
  for_each_field<T>([&](const auto& d) { total += detail::encoded_field_size(value, d); });
  return total;
}

// Appends the wire form of value to out.
template <WireStruct T>
void encode_to(const T& value, std::vector<std::uint8_t>& out) {
  if (const auto problem = detail::find_count_problem(value, "")) {
    throw EncodeError(std::string(T::kWireName) + ": field '" + problem->field + "': count " +
                      std::to_string(problem->count) +
                      (problem->must_equal ? " differs from the " : " exceeds the ") +
                      std::to_string(problem->capacity) + " elements present");
  }
  const std::size_t start = out.size();
  out.resize(start + encoded_size(value));
  std::uint8_t* cursor = out.data() + start;
  for_each_field<T>([&](const auto& d) {
    using D = std::remove_cvref_t<decltype(d)>;
    const auto& member = value.*(d.member);
    if constexpr (is_counted_field_v<D>) {
      const std::size_t n =
          d.wire_carries_count_only ? static_cast<std::size_t>(value.*(d.count)) : member.size();
      for (std::size_t i = 0; i < n; ++i) detail::write_value(cursor, member[i]);
    } else if constexpr (is_tail_field_v<D>) {
      for (const auto& element : member) detail::write_value(cursor, element);
    } else {
      detail::write_value(cursor, member);
    }
  });
}

template <WireStruct T>
std::vector<std::uint8_t> encode(const T& value) {
  std::vector<std::uint8_t> out;
  encode_to(value, out);
  return out;
}

// Decodes one payload. Throws DecodeError when the length does not fit T or a
// count field claims more elements than its array holds.
template <WireStruct T>
T decode(std::span<const std::uint8_t> payload) {
  const std::size_t size = payload.size();
  if (size > kMaxWireSize<T>) throw DecodeError::oversized(T::kWireName, kMaxWireSize<T>, size);

  T value{};
  const std::uint8_t* const begin = payload.data();
  const std::uint8_t* cursor = begin;
  auto remaining = [&] { return size - static_cast<std::size_t>(cursor - begin); };

  for_each_field<T>([&](const auto& d) {
    using D = std::remove_cvref_t<decltype(d)>;
    auto& member = value.*(d.member);
    if constexpr (is_tail_field_v<D>) {
      using Element = typename std::remove_cvref_t<decltype(member)>::value_type;
      constexpr std::size_t element_size = wire_size_of<Element>();
      const std::size_t bytes = remaining();
      if (bytes % element_size != 0) throw DecodeError::ragged(T::kWireName, d.name, element_size, bytes);
      std::size_t present = bytes / element_size;
      std::size_t keep = present;
      if (d.count != nullptr) {
        // A sized tail may arrive padded to the full struct; only `count` elements are data.
        keep = static_cast<std::size_t>(value.*(d.count));
        if (keep > present) throw DecodeError::count_mismatch(T::kWireName, d.name, keep, present);
      }
      member.resize(keep);
      for (auto& element : member) detail::read_value(cursor, element);
      cursor += (present - keep) * element_size;
    } else if constexpr (is_counted_field_v<D>) {
      using Element = typename std::remove_cvref_t<decltype(member)>::value_type;
      constexpr std::size_t element_size = wire_size_of<Element>();
      constexpr std::size_t capacity = std::tuple_size_v<std::remove_cvref_t<decltype(member)>>;
      std::size_t present = capacity;
      if (d.wire_carries_count_only) {
        // The count field precedes this tail, so it is already decoded.
        const auto count = static_cast<std::size_t>(value.*(d.count));
        if (count > capacity) throw DecodeError::bad_count(T::kWireName, d.name, count, capacity);
        const std::size_t bytes = remaining();
        if (bytes < count * element_size) {
          throw DecodeError::truncated(T::kWireName, d.name,
                                       size - bytes + count * element_size, size);
        }
        if (bytes % element_size != 0) throw DecodeError::ragged(T::kWireName, d.name, element_size, bytes);
        present = bytes / element_size;
      } else if (remaining() < capacity * element_size) {
        throw DecodeError::truncated(T::kWireName, d.name, kMinWireSize<T>, size);
      }
      for (std::size_t i = 0; i < present; ++i) detail::read_value(cursor, member[i]);
    } else {
      if (remaining() < field_bytes(d).nominal) {
        throw DecodeError::truncated(T::kWireName, d.name, kMinWireSize<T>, size);
      }
      detail::read_value(cursor, member);
    }
  });

  // Counts are checked once every field is read, because some come after their
  // array (wifi link_count), and nested structs have counts of their own.
  if (const auto problem = detail::find_count_problem(value, "")) {
    if (problem->must_equal) {
      throw DecodeError::count_mismatch(T::kWireName, problem->field, problem->count, problem->capacity);
    }
    throw DecodeError::bad_count(T::kWireName, problem->field, problem->count, problem->capacity);
  }
  return value;
}

}  // namespace playerkit::protocol
