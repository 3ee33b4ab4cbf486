#include "framing/dle_stuffed_format.hpp"

#include <algorithm>
#include <utility>

namespace playerkit::framing {

namespace {

bool needs_escape(std::uint8_t byte, const DleStuffing& s) {
  return byte == s.start || byte == s.end || byte == s.escape;
}

// The byte an escape sequence DLE `code` stands for, or nullopt if `code`
// stands for none (only the three special bytes are ever escaped).
std::optional<std::uint8_t> escaped_byte(std::uint8_t code, const DleStuffing& s) {
  const auto byte = static_cast<std::uint8_t>(code - s.offset);
  if (!needs_escape(byte, s)) return std::nullopt;
  return byte;
}

}  // namespace

DleStuffedFormat::DleStuffedFormat(DleOptions options) : options_(std::move(options)) {
  // Room for the start, the header and the end at least.
  options_.max_length = std::max(options_.max_length, options_.stuffing.raw_header + 2);
}

FrameScan DleStuffedFormat::scan(std::span<const std::uint8_t> buffered) const {
  const DleStuffing& s = options_.stuffing;
  if (buffered.empty()) return FrameScan::need();
  if (buffered.front() != s.start) {
    const auto next = std::find(buffered.begin() + 1, buffered.end(), s.start);
    return FrameScan::noise(static_cast<std::size_t>(next - buffered.begin()));
  }
  const std::size_t body = 1 + s.raw_header;
  if (buffered.size() < body) return FrameScan::need(body);

  const std::size_t limit = std::min(buffered.size(), options_.max_length);
  for (std::size_t i = body; i < limit; ++i) {
    const std::uint8_t byte = buffered[i];
    if (byte == s.end) {
      const std::size_t size = i + 1;
      if (options_.check) {
        const auto content = unstuff(buffered.first(size), s);
        if (!content || !options_.check(*content)) return FrameScan::corrupt(size);
      }
      return FrameScan::whole(size);
    }
    // A start inside: this frame lost its end; the search resumes there.
    if (byte == s.start) return FrameScan::noise(i);
    if (byte == s.escape) {
      if (i + 1 == buffered.size()) return FrameScan::need(i + 2);
      // An escape of a byte that needs none: this was no frame.
      if (!escaped_byte(buffered[i + 1], s)) return FrameScan::noise(1);
      ++i;
    }
  }
  if (buffered.size() >= options_.max_length) return FrameScan::noise(1);
  return FrameScan::need();
}

std::optional<std::vector<std::uint8_t>> unstuff(std::span<const std::uint8_t> frame, const DleStuffing& s) {
  if (frame.size() < s.raw_header + 2 || frame.front() != s.start || frame.back() != s.end) return std::nullopt;
  const auto inside = frame.subspan(1, frame.size() - 2);
  std::vector<std::uint8_t> content(inside.begin(), inside.begin() + static_cast<long>(s.raw_header));
  for (std::size_t i = s.raw_header; i < inside.size(); ++i) {
    const std::uint8_t byte = inside[i];
    if (byte == s.start || byte == s.end) return std::nullopt;
    if (byte != s.escape) {
      content.push_back(byte);
      continue;
    }
    if (i + 1 == inside.size()) return std::nullopt;
    const auto original = escaped_byte(inside[++i], s);
    if (!original) return std::nullopt;
    content.push_back(*original);
  }
  return content;
}

std::vector<std::uint8_t> stuff(std::span<const std::uint8_t> content, const DleStuffing& s) {
  std::vector<std::uint8_t> frame;
  frame.reserve(content.size() + 2);
  frame.push_back(s.start);
  const std::size_t header = std::min(s.raw_header, content.size());
  frame.insert(frame.end(), content.begin(), content.begin() + static_cast<long>(header));
  for (const std::uint8_t byte : content.subspan(header)) {
    if (needs_escape(byte, s)) {
      frame.push_back(s.escape);
      frame.push_back(static_cast<std::uint8_t>(byte + s.offset));
    } else {
      frame.push_back(byte);
    }
  }
  frame.push_back(s.end);
  return frame;
}

}  // namespace playerkit::framing
