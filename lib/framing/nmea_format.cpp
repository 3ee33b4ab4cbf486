#include "framing/nmea_format.hpp"

#include <algorithm>
#include <optional>

namespace playerkit::framing {

namespace {

bool starts_sentence(std::uint8_t byte) { return byte == '$' || byte == '!'; }

// NMEA text is printable ASCII; anything else (bytes received at the wrong
// baud rate, a binary protocol sharing the line) means this is no sentence.
bool printable(std::uint8_t byte) { return byte >= 0x20 && byte <= 0x7e; }

std::optional<std::uint8_t> hex_digit(std::uint8_t c) {
  if (c >= '0' && c <= '9') return static_cast<std::uint8_t>(c - '0');
  if (c >= 'A' && c <= 'F') return static_cast<std::uint8_t>(c - 'A' + 10);
  if (c >= 'a' && c <= 'f') return static_cast<std::uint8_t>(c - 'a' + 10);
  return std::nullopt;
}

// The sentence's text without its line end: `$`...`*hh`.
std::string_view sentence_text(std::span<const std::uint8_t> sentence) {
  std::string_view text(reinterpret_cast<const char*>(sentence.data()), sentence.size());
  if (text.ends_with('\n')) text.remove_suffix(1);
  if (text.ends_with('\r')) text.remove_suffix(1);
  return text;
}

}  // namespace

NmeaFormat::NmeaFormat(NmeaOptions options) : options_(options) {
  // "$*hh\r\n" is the shortest sentence there is.
  options_.max_length = std::max<std::size_t>(options_.max_length, 6);
}

FrameScan NmeaFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return FrameScan::need();
  if (!starts_sentence(buffered.front())) {
    const auto next = std::find_if(buffered.begin() + 1, buffered.end(), starts_sentence);
    return FrameScan::noise(static_cast<std::size_t>(next - buffered.begin()));
  }
  // Walk the sentence: every byte up to the LF must be text; a start
  // character inside means this one lost its end, and the search resumes there.
  const std::size_t limit = std::min(buffered.size(), options_.max_length);
  std::size_t end = 0;
  for (std::size_t i = 1; i < limit; ++i) {
    const std::uint8_t byte = buffered[i];
    if (byte == '\n') {
      end = i + 1;
      break;
    }
    if (byte == '\r') {
      if (i + 1 == buffered.size()) return FrameScan::need(i + 2);
      if (buffered[i + 1] != '\n') return FrameScan::noise(i + 1);
      continue;
    }
    if (starts_sentence(byte)) return FrameScan::noise(i);
    if (!printable(byte)) return FrameScan::noise(i + 1);
  }
  if (end == 0) {
    if (buffered.size() >= options_.max_length) return FrameScan::noise(1);
    return FrameScan::need();
  }

  const std::string_view text = sentence_text(buffered.first(end));
  const auto star = text.rfind('*');
  if (star == std::string_view::npos) {
    return options_.accept_missing_checksum ? FrameScan::whole(end) : FrameScan::corrupt(end);
  }
  // `*` must be followed by exactly two hex digits; anything else is a
  // damaged checksum field.
  if (text.size() != star + 3) return FrameScan::corrupt(end);
  const auto high = hex_digit(static_cast<std::uint8_t>(text[star + 1]));
  const auto low = hex_digit(static_cast<std::uint8_t>(text[star + 2]));
  if (!high || !low) return FrameScan::corrupt(end);
  const auto sent = static_cast<std::uint8_t>((*high << 4) | *low);
  return sent == nmea_checksum(text.substr(1, star - 1)) ? FrameScan::whole(end) : FrameScan::corrupt(end);
}

std::uint8_t nmea_checksum(std::string_view body) {
  std::uint8_t sum = 0;
  for (const char c : body) sum = static_cast<std::uint8_t>(sum ^ static_cast<std::uint8_t>(c));
  return sum;
}

std::vector<std::uint8_t> nmea_sentence(std::string_view body, char start) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::vector<std::uint8_t> bytes;
  bytes.reserve(body.size() + 6);
  bytes.push_back(static_cast<std::uint8_t>(start));
  bytes.insert(bytes.end(), body.begin(), body.end());
  const std::uint8_t sum = nmea_checksum(body);
  for (const char c : {'*', kDigits[sum >> 4], kDigits[sum & 0x0f], '\r', '\n'}) {
    bytes.push_back(static_cast<std::uint8_t>(c));
  }
  return bytes;
}

std::string_view nmea_body(std::span<const std::uint8_t> sentence) {
  std::string_view text = sentence_text(sentence);
  if (!text.empty() && starts_sentence(static_cast<std::uint8_t>(text.front()))) text.remove_prefix(1);
  const auto star = text.rfind('*');
  return star == std::string_view::npos ? text : text.substr(0, star);
}

}  // namespace playerkit::framing
