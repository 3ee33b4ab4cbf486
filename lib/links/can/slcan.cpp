#include "links/can/slcan.hpp"

#include <array>
#include <cstdio>

namespace playerkit::links::can {

namespace {

constexpr std::array<int, 9> kBitrates{10000, 20000, 50000, 100000, 125000, 250000, 500000, 800000, 1000000};

std::optional<std::uint32_t> hex_value(std::string_view digits) {
  std::uint32_t value = 0;
  for (const char digit : digits) {
    value <<= 4;
    if (digit >= '0' && digit <= '9') {
      value |= static_cast<std::uint32_t>(digit - '0');
    } else if (digit >= 'A' && digit <= 'F') {
      value |= static_cast<std::uint32_t>(digit - 'A' + 10);
    } else if (digit >= 'a' && digit <= 'f') {
      value |= static_cast<std::uint32_t>(digit - 'a' + 10);
    } else {
      return std::nullopt;
    }
  }
  return value;
}

void append_hex(std::string& text, std::uint32_t value, int digits) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  for (int shift = (digits - 1) * 4; shift >= 0; shift -= 4) text.push_back(kDigits[(value >> shift) & 0xF]);
}

}  // namespace

std::string slcan_frame_line(const framing::CanFrame& frame) {
  std::string line;
  line.reserve(kLongestSlcanLine);
  const char kind = frame.remote ? 'r' : 't';
  line.push_back(frame.extended ? static_cast<char>(kind - 'a' + 'A') : kind);
  append_hex(line, frame.id, frame.extended ? 8 : 3);
  append_hex(line, frame.dlc, 1);
  if (!frame.remote) {
    for (std::uint8_t index = 0; index < frame.dlc && index < 8; ++index) append_hex(line, frame.data[index], 2);
  }
  line.push_back(kSlcanEnd);
  return line;
}

std::optional<framing::CanFrame> parse_slcan_frame(std::string_view line) {
  if (line.empty()) return std::nullopt;
  const char kind = line.front();
  framing::CanFrame frame;
  if (kind == 't' || kind == 'r') {
    frame.extended = false;
  } else if (kind == 'T' || kind == 'R') {
    frame.extended = true;
  } else {
    return std::nullopt;
  }
  frame.remote = kind == 'r' || kind == 'R';
  const std::size_t id_digits = frame.extended ? 8 : 3;
  if (line.size() < 1 + id_digits + 1) return std::nullopt;
  const auto id = hex_value(line.substr(1, id_digits));
  const auto dlc = hex_value(line.substr(1 + id_digits, 1));
  if (!id || !dlc || *dlc > 8) return std::nullopt;
  if (*id > (frame.extended ? framing::kCanExtendedIdMask : framing::kCanStandardIdMask)) return std::nullopt;
  frame.id = *id;
  frame.dlc = static_cast<std::uint8_t>(*dlc);
  const std::string_view data = line.substr(2 + id_digits);
  // Some adapters append a 4-digit timestamp (Z1): allowed, ignored.
  const std::size_t data_digits = frame.remote ? 0 : 2u * frame.dlc;
  if (data.size() != data_digits && data.size() != data_digits + 4) return std::nullopt;
  for (std::size_t index = 0; index * 2 < data_digits; ++index) {
    const auto byte = hex_value(data.substr(index * 2, 2));
    if (!byte) return std::nullopt;
    frame.data[index] = static_cast<std::uint8_t>(*byte);
  }
  if (data.size() > data_digits && !hex_value(data.substr(data_digits))) return std::nullopt;
  return frame;
}

std::optional<std::string> slcan_bitrate_command(int bits_per_second) {
  for (std::size_t code = 0; code < kBitrates.size(); ++code) {
    if (kBitrates[code] == bits_per_second) return std::string{'S', static_cast<char>('0' + code), kSlcanEnd};
  }
  return std::nullopt;
}

std::optional<int> slcan_bitrate_of(char code) {
  if (code < '0' || code > '8') return std::nullopt;
  return kBitrates[static_cast<std::size_t>(code - '0')];
}

const std::vector<int>& slcan_bitrates() {
  static const std::vector<int> rates(kBitrates.begin(), kBitrates.end());
  return rates;
}

framing::FrameScan SlcanFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return framing::FrameScan::need();
  if (buffered.front() == static_cast<std::uint8_t>(kSlcanRefusal)) return framing::FrameScan::whole(1);
  if (buffered.front() == '\n') return framing::FrameScan::noise(1);
  for (std::size_t index = 0; index < buffered.size(); ++index) {
    const std::uint8_t byte = buffered[index];
    if (byte == static_cast<std::uint8_t>(kSlcanEnd)) return framing::FrameScan::whole(index + 1);
    // A BEL or LF inside a line: what came before it was no line.
    if (byte == static_cast<std::uint8_t>(kSlcanRefusal) || byte == '\n') return framing::FrameScan::noise(index);
    if (index + 1 >= kLongestSlcanLine) return framing::FrameScan::noise(index + 1);
  }
  return framing::FrameScan::need();
}

std::string_view slcan_text(std::span<const std::uint8_t> telegram) {
  std::string_view text(reinterpret_cast<const char*>(telegram.data()), telegram.size());
  if (!text.empty() && text.back() == kSlcanEnd) text.remove_suffix(1);
  return text;
}

}  // namespace playerkit::links::can
