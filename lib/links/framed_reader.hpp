#pragma once
// Whole telegrams from a ByteLink, cut by a framing::FrameFormat.
//
//   links::FramedReader reader(*link, p2os_format);
//   while (auto telegram = reader.next(links::deadline_in(500ms))) handle(*telegram);
//
// Noise before a telegram is skipped (one resync per run of noise), a
// telegram failing its checksum is dropped (a checksum error), and the
// search resumes one byte after its start: if the corruption hit the length
// byte, real telegrams hidden inside the bogus span are still found. A
// declared length beyond `max_telegram` is noise, never a reason to wait.
// Everything dropped is counted in the link's counters.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "framing/frame_format.hpp"
#include "links/byte_link.hpp"

namespace playerkit::links {

class FramedReader {
 public:
  // Both must outlive the reader. `max_telegram`: the longest telegram the
  // protocol can send (P2OS 258 bytes, SICK LMS ~ 812).
  FramedReader(ByteLink& link, const framing::FrameFormat& format, std::size_t max_telegram = 4096);

  // The next whole valid telegram, or nullopt when the deadline passes first
  // (counted as a timeout; a partial telegram stays buffered for the next
  // call). LinkErrors from the link pass through.
  std::optional<std::vector<std::uint8_t>> next(Deadline deadline);

  // Drops buffered bytes and the link's pending input: before a request
  // whose reply must not be confused with older traffic.
  void flush();

  [[nodiscard]] std::size_t buffered() const { return buffer_.size() - start_; }
  [[nodiscard]] std::size_t max_telegram() const { return max_telegram_; }
  ByteLink& link() { return link_; }

 private:
  enum class Verdict { telegram, need_more, dropped };
  Verdict judge_front(std::optional<std::vector<std::uint8_t>>& telegram);
  void drop_front(std::size_t count, bool noise);
  void fill(std::size_t wanted_total, Deadline deadline, bool& timed_out);

  ByteLink& link_;
  const framing::FrameFormat& format_;
  std::size_t max_telegram_;
  std::vector<std::uint8_t> buffer_;
  std::size_t start_ = 0;       // first unconsumed byte of buffer_
  std::size_t wanted_ = 0;      // buffered size at which scanning again is useful
  bool in_noise_ = false;       // inside a run of dropped bytes (one resync per run)
};

}  // namespace playerkit::links
