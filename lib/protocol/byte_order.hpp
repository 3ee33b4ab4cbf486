#pragma once
// Big-endian (network order) loads and stores for every integer width Player uses.
// Player 1.5 puts every multi-byte field on the wire most significant byte first,
// int64 included (its htonll is a full 64-bit swap).

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <type_traits>

namespace playerkit::protocol {

template <std::integral T>
constexpr void store_be(std::uint8_t* out, T value) noexcept {
  using U = std::make_unsigned_t<T>;
  auto bits = static_cast<U>(value);
  for (std::size_t i = sizeof(T); i-- > 0;) {
    out[i] = static_cast<std::uint8_t>(bits & 0xFFu);
    if constexpr (sizeof(T) > 1) bits = static_cast<U>(bits >> 8);
  }
}

template <std::integral T>
constexpr T load_be(const std::uint8_t* in) noexcept {
  using U = std::make_unsigned_t<T>;
  U bits = 0;
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    if constexpr (sizeof(T) > 1) bits = static_cast<U>(bits << 8);
    bits = static_cast<U>(bits | in[i]);
  }
  return static_cast<T>(bits);
}

}  // namespace playerkit::protocol
