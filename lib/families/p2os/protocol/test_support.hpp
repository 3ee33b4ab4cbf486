#pragma once
// For the tests of lib/families/p2os/protocol: bytes written as the sheet prints them.

#include <cstdint>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::hardware::p2os::testing {

// "FA FB 03 00 00 00" -> bytes.
inline std::vector<std::uint8_t> hex(std::string_view text) {
  std::vector<std::uint8_t> bytes;
  std::istringstream in{std::string(text)};
  std::string word;
  while (in >> word) bytes.push_back(static_cast<std::uint8_t>(std::stoul(word, nullptr, 16)));
  return bytes;
}

// The worked examples of p2os.md §1.1, §2.2 and §2.3, byte for byte.
namespace golden {
inline constexpr std::string_view sync0 = "FA FB 03 00 00 00";
inline constexpr std::string_view open = "FA FB 03 01 00 01";
inline constexpr std::string_view enable_1 = "FA FB 06 04 3B 01 00 05 3B";
inline constexpr std::string_view vel2_right5_left5 = "FA FB 06 20 3B 05 05 25 40";
inline constexpr std::string_view vel_minus_300 = "FA FB 06 0B 1B 2C 01 37 1C";
inline constexpr std::string_view seto = "FA FB 04 07 3B 07 3B";
inline constexpr std::string_view sync2_myrobot =
    "FA FB 18 02 4D 79 52 6F 62 6F 74 00 50 69 6F 6E 65 65 72 00 70 33 64 78 00 43 DF";
inline constexpr std::string_view sip =
    "FA FB 21 32 64 00 00 00 00 04 00 00 00 00 78 00 00 00 00 01 00 2E 02 00 F4 01 01 E8 03 "
    "05 01 00 00 00 54 D7";
}  // namespace golden

}  // namespace playerkit::hardware::p2os::testing
