#pragma once
// A fixed-size, NUL-padded text field such as driver_name[64] or ip[32].
// On the wire it is exactly N bytes; in C++ and JSON it is text.

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

namespace playerkit::protocol {

template <std::size_t N>
struct FixedString {
  static constexpr std::size_t kCapacity = N;
  std::array<char, N> bytes{};

  FixedString() = default;
  // Implicit on purpose: `reply.driver_name = "readlog";` reads naturally.
  FixedString(std::string_view text) { assign(text); }  // NOLINT(google-explicit-constructor)
  FixedString(const char* text) : FixedString(std::string_view(text)) {}  // NOLINT

  // The text up to the first NUL (or all N bytes when the field is full).
  [[nodiscard]] std::string_view view() const {
    const auto end = std::find(bytes.begin(), bytes.end(), '\0');
    return {bytes.data(), static_cast<std::size_t>(end - bytes.begin())};
  }
  [[nodiscard]] std::string str() const { return std::string(view()); }

  // Keeps room for the terminating NUL, because C clients strcpy these fields.
  void assign(std::string_view text) {
    if (text.size() >= N) {
      throw std::length_error("text of " + std::to_string(text.size()) +
                              " characters does not fit a " + std::to_string(N) +
                              "-byte field (at most " + std::to_string(N - 1) + ")");
    }
    bytes.fill('\0');
    std::copy(text.begin(), text.end(), bytes.begin());
  }

  friend bool operator==(const FixedString&, const FixedString&) = default;
};

template <class T>
inline constexpr bool is_fixed_string_v = false;
template <std::size_t N>
inline constexpr bool is_fixed_string_v<FixedString<N>> = true;

}  // namespace playerkit::protocol
