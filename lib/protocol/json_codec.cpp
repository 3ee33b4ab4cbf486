#include "protocol/json_codec.hpp"

#include <cmath>

namespace playerkit::protocol::detail {

std::string latin1_to_utf8(std::string_view bytes) {
  std::string out;
  out.reserve(bytes.size());
  for (char c : bytes) {
    const auto b = static_cast<unsigned char>(c);
    if (b < 0x80) {
      out.push_back(c);
    } else {
      out.push_back(static_cast<char>(0xC0 | (b >> 6)));
      out.push_back(static_cast<char>(0x80 | (b & 0x3F)));
    }
  }
  return out;
}

std::string utf8_to_latin1(std::string_view text, const std::string& path) {
  std::string out;
  out.reserve(text.size());
  for (std::size_t i = 0; i < text.size(); ++i) {
    const auto b = static_cast<unsigned char>(text[i]);
    if (b < 0x80) {
      out.push_back(static_cast<char>(b));
      continue;
    }
    // Only U+0080..U+00FF (two-byte sequences led by 0xC2 or 0xC3) map to one byte.
    if ((b == 0xC2 || b == 0xC3) && i + 1 < text.size()) {
      const auto next = static_cast<unsigned char>(text[i + 1]);
      if ((next & 0xC0) == 0x80) {
        out.push_back(static_cast<char>(((b & 0x03) << 6) | (next & 0x3F)));
        ++i;
        continue;
      }
    }
    throw JsonError(path + ": character at byte " + std::to_string(i) +
                    " is outside U+0000..U+00FF; text fields hold single bytes");
  }
  return out;
}

void throw_json_type(const std::string& path, std::string_view wanted, const nlohmann::json& got) {
  throw JsonError(path + ": expected " + std::string(wanted) + ", got " + got.type_name() + " " +
                  got.dump());
}

std::int64_t json_integer(const nlohmann::json& j, const std::string& path, std::int64_t min,
                          std::uint64_t max) {
  auto out_of_range = [&]() -> JsonError {
    return JsonError(path + ": " + j.dump() + " is out of range [" + std::to_string(min) + ", " +
                     std::to_string(max) + "]");
  };
  if (j.is_number_unsigned()) {
    const auto v = j.get<std::uint64_t>();
    if (v > max) throw out_of_range();
    return static_cast<std::int64_t>(v);
  }
  if (j.is_number_integer()) {
    const auto v = j.get<std::int64_t>();
    if (v < min || (v > 0 && static_cast<std::uint64_t>(v) > max)) throw out_of_range();
    return v;
  }
  if (j.is_number_float()) {
    // Accept 5.0 (some tools print every number as a double) but not 5.5.
    const double v = j.get<double>();
    // The range first: converting a double beyond int64 is undefined (9e102
    // from a fuzzer). 2^63 itself is already beyond.
    constexpr double kBeyondInt64 = 9223372036854775808.0;
    if (!(v >= static_cast<double>(min) && v <= static_cast<double>(max)) || v >= kBeyondInt64) {
      throw out_of_range();
    }
    if (std::trunc(v) != v) throw JsonError(path + ": expected an integer, got " + j.dump());
    return static_cast<std::int64_t>(v);
  }
  if (j.is_boolean()) return j.get<bool>() ? 1 : 0;
  throw_json_type(path, "an integer", j);
}

}  // namespace playerkit::protocol::detail
