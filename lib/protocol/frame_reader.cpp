#include "protocol/frame_reader.hpp"

#include <algorithm>

#include "protocol/constants.hpp"

namespace playerkit::protocol {

namespace {

constexpr std::uint8_t kStxFirst = kStx >> 8;     // 'X'
constexpr std::uint8_t kStxSecond = kStx & 0xFF;  // 'x'

}  // namespace

void FrameReader::drop(std::size_t count) { start_ += count; }

void FrameReader::flush_skipped(std::vector<FrameEvent>& events) {
  if (skipped_ == 0) return;
  events.emplace_back(SkippedBytes{skipped_});
  skipped_ = 0;
}

std::vector<FrameEvent> FrameReader::feed(std::span<const std::uint8_t> bytes) {
  // Compact before growing so the buffer stays about one message long.
  if (start_ > 0) {
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(start_));
    start_ = 0;
  }
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());

  std::vector<FrameEvent> events;
  for (;;) {
    const std::span<const std::uint8_t> pending(buffer_.data() + start_, buffer_.size() - start_);
    if (body_to_discard_ > 0) {
      const std::size_t n = std::min(body_to_discard_, pending.size());
      drop(n);
      body_to_discard_ -= n;
      if (body_to_discard_ > 0) break;
      continue;
    }
    if (pending.size() < 2) break;
    if (pending[0] != kStxFirst || pending[1] != kStxSecond) {
      // Skip to the next possible marker; keep a trailing 'X' that may be its first half.
      std::size_t next = 1;
      while (next + 1 < pending.size() &&
             !(pending[next] == kStxFirst && pending[next + 1] == kStxSecond)) {
        ++next;
      }
      if (next + 1 == pending.size() && pending[next] != kStxFirst) ++next;
      skipped_ += next;
      drop(next);
      continue;
    }
    if (pending.size() < kHeaderSize) break;
    const MessageHeader header =
        decode_header(pending.first<kHeaderSize>());
    if (header.size > max_payload_) {
      if (header.size > std::max(kMaxSkippableSize, max_payload_)) {
        skipped_ += 2;  // not a header after all: scan on from the next byte pair
        drop(2);
        continue;
      }
      flush_skipped(events);
      events.emplace_back(OversizeMessage{header});
      drop(kHeaderSize);
      body_to_discard_ = header.size;
      continue;
    }
    const std::size_t total = kHeaderSize + header.size;
    if (pending.size() < total) break;
    flush_skipped(events);
    Message message;
    message.header = header;
    message.payload.assign(pending.begin() + kHeaderSize,
                           pending.begin() + static_cast<std::ptrdiff_t>(total));
    events.emplace_back(std::move(message));
    drop(total);
  }
  return events;
}

}  // namespace playerkit::protocol
