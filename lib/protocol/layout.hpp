#pragma once
// Compile-time sizes and offsets of wire structs, derived from their field lists.
// "Nominal" is the spec's view: every array full, every tail at its nominal count,
// so nominal offsets and sizes must equal the tables of wire-format.md.

#include <array>
#include <cstddef>
#include <string_view>
#include <tuple>

#include "protocol/fields.hpp"

namespace playerkit::protocol {

struct FieldBytes {
  std::size_t min = 0;      // fewest bytes a valid payload holds for this field
  std::size_t nominal = 0;  // bytes in the spec's struct
  std::size_t max = 0;      // most bytes a valid payload holds for this field
};

template <class V>
constexpr std::size_t wire_size_of();

template <class O, class M>
constexpr FieldBytes field_bytes(const PlainField<O, M>&) {
  constexpr std::size_t n = wire_size_of<M>();
  return {n, n, n};
}

template <class O, class E, std::size_t N, class C>
constexpr FieldBytes field_bytes(const CountedField<O, E, N, C>& d) {
  const std::size_t full = N * wire_size_of<E>();
  return {d.wire_carries_count_only ? 0 : full, full, full};
}

template <class O, class E, class C>
constexpr FieldBytes field_bytes(const TailField<O, E, C>& d) {
  return {0, d.nominal_count * wire_size_of<E>(), d.max_count * wire_size_of<E>()};
}

template <WireStruct T>
constexpr FieldBytes struct_bytes() {
  FieldBytes total;
  for_each_field<T>([&](const auto& d) {
    const FieldBytes b = field_bytes(d);
    total.min += b.min;
    total.nominal += b.nominal;
    total.max += b.max;
  });
  return total;
}

template <class V>
constexpr std::size_t wire_size_of() {
  if constexpr (std::is_integral_v<V>) {
    return sizeof(V);
  } else if constexpr (is_std_array_v<V>) {
    return std::tuple_size_v<V> * wire_size_of<typename V::value_type>();
  } else if constexpr (is_fixed_string_v<V>) {
    return V::kCapacity;
  } else {
    static_assert(WireStruct<V>, "not a wire type");
    return struct_bytes<V>().nominal;
  }
}

// Payload sizes a decoder accepts for T.
template <WireStruct T>
inline constexpr std::size_t kMinWireSize = struct_bytes<T>().min;
template <WireStruct T>
inline constexpr std::size_t kMaxWireSize = struct_bytes<T>().max;

template <WireStruct T>
inline constexpr std::size_t kFieldCount = std::tuple_size_v<decltype(T::fields())>;

struct FieldLayout {
  std::string_view name;
  std::size_t offset = 0;  // nominal offset from the start of the payload
  std::size_t size = 0;    // nominal size
};

template <WireStruct T>
constexpr std::array<FieldLayout, kFieldCount<T>> field_layout() {
  std::array<FieldLayout, kFieldCount<T>> out{};
  std::size_t i = 0;
  std::size_t offset = 0;
  for_each_field<T>([&](const auto& d) {
    const std::size_t size = field_bytes(d).nominal;
    out[i++] = FieldLayout{d.name, offset, size};
    offset += size;
  });
  return out;
}

// True when the field list adds up to the size the spec states for the struct.
template <WireStruct T>
constexpr bool layout_matches_spec() {
  return struct_bytes<T>().nominal == T::kWireSize;
}

}  // namespace playerkit::protocol
