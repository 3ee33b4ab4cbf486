#include "text/printable.hpp"

#include <cstdint>
#include <cstdio>

namespace playerkit::text {
namespace {

constexpr std::string_view kEllipsis = "\u2026";

std::string hex_byte(unsigned char byte) {
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "\\x%02x", byte);
  return buffer;
}

std::string code_point_escape(std::uint32_t code_point) {
  char buffer[12];
  std::snprintf(buffer, sizeof buffer, "\\u%04x", static_cast<unsigned>(code_point));
  return buffer;
}

// Code points a terminal or a text renderer acts on rather than shows: C1
// controls (0x9b is a CSI on some terminals), line and paragraph separators,
// and the bidirectional controls that reorder what follows them.
bool is_invisible_control(std::uint32_t code_point) {
  return (code_point >= 0x80 && code_point <= 0x9f) || code_point == 0x2028 || code_point == 0x2029 ||
         (code_point >= 0x200e && code_point <= 0x200f) || (code_point >= 0x202a && code_point <= 0x202e) ||
         (code_point >= 0x2066 && code_point <= 0x2069);
}

// One character of input: how many bytes it takes and how it is shown.
struct Unit {
  std::size_t length = 1;
  std::string shown;
};

// The length of the well-formed UTF-8 sequence at the start of `text` and its
// code point, or 0 when it is not one (stray continuation byte, overlong
// form, surrogate, beyond U+10FFFF, cut short).
std::size_t utf8_sequence(std::string_view text, std::uint32_t& code_point) {
  const auto lead = static_cast<unsigned char>(text[0]);
  std::size_t length = 0;
  std::uint32_t minimum = 0;
  if (lead >= 0xc2 && lead <= 0xdf) {
    length = 2;
    minimum = 0x80;
    code_point = lead & 0x1fu;
  } else if (lead >= 0xe0 && lead <= 0xef) {
    length = 3;
    minimum = 0x800;
    code_point = lead & 0x0fu;
  } else if (lead >= 0xf0 && lead <= 0xf4) {
    length = 4;
    minimum = 0x10000;
    code_point = lead & 0x07u;
  } else {
    return 0;
  }
  if (text.size() < length) return 0;
  for (std::size_t i = 1; i < length; ++i) {
    const auto byte = static_cast<unsigned char>(text[i]);
    if ((byte & 0xc0u) != 0x80u) return 0;
    code_point = (code_point << 6) | (byte & 0x3fu);
  }
  if (code_point < minimum || code_point > 0x10ffff || (code_point >= 0xd800 && code_point <= 0xdfff)) return 0;
  return length;
}

Unit next_unit(std::string_view text) {
  const auto byte = static_cast<unsigned char>(text[0]);
  if (byte >= 0x20 && byte < 0x7f) return {1, std::string(1, static_cast<char>(byte))};
  switch (byte) {
    case '\n': return {1, "\\n"};
    case '\r': return {1, "\\r"};
    case '\t': return {1, "\\t"};
    default: break;
  }
  if (byte < 0x80) return {1, hex_byte(byte)};  // other C0 controls and DEL
  std::uint32_t code_point = 0;
  const std::size_t length = utf8_sequence(text, code_point);
  if (length == 0) return {1, hex_byte(byte)};
  if (is_invisible_control(code_point)) return {length, code_point_escape(code_point)};
  return {length, std::string(text.substr(0, length))};
}

}  // namespace

std::string printable(std::string_view text) {
  std::string shown;
  shown.reserve(text.size());
  while (!text.empty()) {
    const Unit unit = next_unit(text);
    shown += unit.shown;
    text.remove_prefix(unit.length);
  }
  return shown;
}

std::string excerpt(std::string_view text, std::size_t max_bytes) {
  std::string shown;
  while (!text.empty()) {
    const Unit unit = next_unit(text);
    if (shown.size() + unit.shown.size() > max_bytes) {
      shown += kEllipsis;
      return shown;
    }
    shown += unit.shown;
    text.remove_prefix(unit.length);
  }
  return shown;
}

std::string describe_character(char c) {
  const auto byte = static_cast<unsigned char>(c);
  if (byte >= 0x20 && byte < 0x7F) return std::string("character '") + c + "'";
  char hex[8];
  std::snprintf(hex, sizeof hex, "0x%02X", byte);
  return std::string("byte ") + hex;
}

}  // namespace playerkit::text
