#pragma once
// How a wire struct describes its fields, in order, so that one generic
// implementation can encode, decode, size-check and JSON-convert all of them.
//
//   struct LaserGeom {
//     static constexpr std::string_view kWireName = "player_laser_geom_t";
//     static constexpr std::size_t kWireSize = 11;   // from the spec table
//     std::uint8_t subtype = 0;
//     std::array<std::int16_t, 3> pose{};
//     std::array<std::int16_t, 2> size{};
//     static constexpr auto fields() {
//       return std::tuple{field("subtype", &LaserGeom::subtype), ...};
//     }
//   };
//
// Field kinds:
//   field(name, &T::m)                  always present, fixed size
//   counted(name, &T::arr, &T::count)   fixed-size array; only `count` elements are
//                                       meaningful (JSON shows those), the wire carries all
//   counted_tail(name, &T::arr, &T::n)  last field; the wire carries only `n` elements
//                                       (localize hypotheses: 14 + 88 * n bytes)
//   tail(name, &T::vec, nominal, max)   last field; as many elements as the payload
//                                       holds (blobfinder blobs, comms bytes)
//   sized_tail(name, &T::vec, &T::n, nominal, max)
//                                       a tail of `n` elements, the count field
//                                       preceding it; a payload padded beyond `n`
//                                       (the full C struct) is accepted, the padding
//                                       dropped (camera image_size)

#include <array>
#include <cstddef>
#include <cstdint>
#include <string_view>
#include <tuple>
#include <type_traits>
#include <vector>

#include "protocol/fixed_string.hpp"

namespace playerkit::protocol {

template <class Owner, class Member>
struct PlainField {
  std::string_view name;
  Member Owner::*member;
};

template <class Owner, class Element, std::size_t N, class Count>
struct CountedField {
  std::string_view name;
  std::array<Element, N> Owner::*member;
  Count Owner::*count;
  bool wire_carries_count_only;  // true for counted_tail
};

template <class Owner, class Element, class Count = std::uint32_t>
struct TailField {
  std::string_view name;
  std::vector<Element> Owner::*member;
  std::size_t nominal_count;  // the element count the spec's struct size assumes
  std::size_t max_count;
  Count Owner::*count = nullptr;  // a field that must equal the element count, if any
};

template <class Owner, class Member>
constexpr PlainField<Owner, Member> field(std::string_view name, Member Owner::*member) {
  return {name, member};
}

template <class Owner, class Element, std::size_t N, class Count>
constexpr CountedField<Owner, Element, N, Count> counted(std::string_view name,
                                                         std::array<Element, N> Owner::*member,
                                                         Count Owner::*count) {
  return {name, member, count, false};
}

template <class Owner, class Element, std::size_t N, class Count>
constexpr CountedField<Owner, Element, N, Count> counted_tail(std::string_view name,
                                                              std::array<Element, N> Owner::*member,
                                                              Count Owner::*count) {
  return {name, member, count, true};
}

template <class Owner, class Element>
constexpr TailField<Owner, Element> tail(std::string_view name,
                                         std::vector<Element> Owner::*member,
                                         std::size_t nominal_count, std::size_t max_count) {
  return {name, member, nominal_count, max_count, nullptr};
}

// A tail whose length another field states (camera: image_size).
template <class Owner, class Element, class Count>
constexpr TailField<Owner, Element, Count> sized_tail(std::string_view name,
                                                      std::vector<Element> Owner::*member,
                                                      Count Owner::*count,
                                                      std::size_t nominal_count,
                                                      std::size_t max_count) {
  return {name, member, nominal_count, max_count, count};
}

// A struct that travels on the wire: it names its C struct, states the spec's size
// and lists its fields.
template <class T>
concept WireStruct = requires {
  { T::kWireName } -> std::convertible_to<std::string_view>;
  { T::kWireSize } -> std::convertible_to<std::size_t>;
  T::fields();
};

template <class T>
inline constexpr bool is_std_array_v = false;
template <class E, std::size_t N>
inline constexpr bool is_std_array_v<std::array<E, N>> = true;

template <class F>
inline constexpr bool is_counted_field_v = false;
template <class O, class E, std::size_t N, class C>
inline constexpr bool is_counted_field_v<CountedField<O, E, N, C>> = true;

template <class F>
inline constexpr bool is_tail_field_v = false;
template <class O, class E, class C>
inline constexpr bool is_tail_field_v<TailField<O, E, C>> = true;

// Calls fn(descriptor) for each field of T, in wire order.
template <WireStruct T, class Fn>
constexpr void for_each_field(Fn&& fn) {
  std::apply([&](const auto&... descriptor) { (fn(descriptor), ...); }, T::fields());
}

}  // namespace playerkit::protocol
