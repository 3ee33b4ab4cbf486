#include "framing/terminated_line_format.hpp"

#include <algorithm>
#include <utility>

namespace playerkit::framing {

namespace {

constexpr std::uint8_t kCarriageReturn = '\r';
constexpr std::uint8_t kLineFeed = '\n';

}  // namespace

TerminatedLineFormat::TerminatedLineFormat(LineOptions options) : options_(std::move(options)) {
  // A line needs room for at least its terminator, or nothing would ever be a telegram.
  options_.max_length = std::max<std::size_t>(options_.max_length, 2);
}

std::optional<TerminatedLineFormat::End> TerminatedLineFormat::find_end(std::span<const std::uint8_t> buffered) const {
  const auto at = [&](auto position) { return static_cast<std::size_t>(position - buffered.begin()); };
  switch (options_.end) {
    case LineEnd::lf: {
      const auto lf = std::find(buffered.begin(), buffered.end(), kLineFeed);
      if (lf == buffered.end()) return std::nullopt;
      return End{at(lf), 1};
    }
    case LineEnd::cr: {
      const auto cr = std::find(buffered.begin(), buffered.end(), kCarriageReturn);
      if (cr == buffered.end()) return std::nullopt;
      return End{at(cr), 1};
    }
    case LineEnd::crlf: {
      const std::uint8_t pair[] = {kCarriageReturn, kLineFeed};
      const auto crlf = std::search(buffered.begin(), buffered.end(), std::begin(pair), std::end(pair));
      if (crlf == buffered.end()) return std::nullopt;
      return End{at(crlf), 2};
    }
    case LineEnd::cr_or_lf: {
      const auto end = std::find_if(buffered.begin(), buffered.end(),
                                    [](std::uint8_t b) { return b == kCarriageReturn || b == kLineFeed; });
      if (end == buffered.end()) return std::nullopt;
      const std::size_t position = at(end);
      // A CR that is the last byte buffered ends the line now: waiting for a
      // possible LF would stall a device that ends lines with CR alone. If the
      // LF comes later, scan() drops it at the front.
      const bool pair =
          *end == kCarriageReturn && position + 1 < buffered.size() && buffered[position + 1] == kLineFeed;
      return End{position, pair ? 2u : 1u};
    }
  }
  return std::nullopt;
}

FrameScan TerminatedLineFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return FrameScan::need();
  if (options_.prompt && buffered.front() == *options_.prompt) return FrameScan::whole(1);
  // In this mode a line never starts with LF: it is the second half of a
  // CR LF pair whose CR ended the previous line before the LF arrived.
  if (options_.end == LineEnd::cr_or_lf && buffered.front() == kLineFeed) return FrameScan::noise(1);

  if (const auto end = find_end(buffered)) {
    const std::size_t size = end->at + end->size;
    // An overlong line goes with its terminator, so the next line starts clean.
    if (size > options_.max_length) return FrameScan::noise(size);
    if (end->at == 0 && options_.skip_empty_lines) return FrameScan::noise(size);
    return FrameScan::whole(size);
  }
  // Everything buffered belongs to one line that is already too long.
  if (buffered.size() >= options_.max_length) return FrameScan::noise(buffered.size());
  return FrameScan::need();
}

std::string_view line_text(std::span<const std::uint8_t> telegram) {
  std::string_view text(reinterpret_cast<const char*>(telegram.data()), telegram.size());
  if (text.ends_with("\r\n")) {
    text.remove_suffix(2);
  } else if (text.ends_with('\n') || text.ends_with('\r')) {
    text.remove_suffix(1);
  }
  return text;
}

std::vector<std::uint8_t> line_bytes(std::string_view text, LineEnd end) {
  std::vector<std::uint8_t> bytes(text.begin(), text.end());
  switch (end) {
    case LineEnd::lf: bytes.push_back(kLineFeed); break;
    case LineEnd::cr: bytes.push_back(kCarriageReturn); break;
    case LineEnd::crlf:
    case LineEnd::cr_or_lf:
      bytes.push_back(kCarriageReturn);
      bytes.push_back(kLineFeed);
      break;
  }
  return bytes;
}

}  // namespace playerkit::framing
