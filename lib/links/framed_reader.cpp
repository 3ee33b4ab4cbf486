#include "links/framed_reader.hpp"

#include <algorithm>

namespace playerkit::links {

namespace {

constexpr std::size_t kReadChunk = 4096;

}  // namespace

FramedReader::FramedReader(ByteLink& link, const framing::FrameFormat& format, std::size_t max_telegram)
    : link_(link), format_(format), max_telegram_(std::max<std::size_t>(max_telegram, 1)) {}

std::optional<std::vector<std::uint8_t>> FramedReader::next(Deadline deadline) {
  while (true) {
    while (buffered() > 0 && buffered() >= wanted_) {
      std::optional<std::vector<std::uint8_t>> telegram;
      const Verdict verdict = judge_front(telegram);
      if (verdict == Verdict::telegram) return telegram;
      if (verdict == Verdict::need_more) break;
    }
    bool timed_out = false;
    fill(wanted_, deadline, timed_out);
    if (timed_out) {
      link_.counters().timeouts.add();
      return std::nullopt;
    }
  }
}

FramedReader::Verdict FramedReader::judge_front(std::optional<std::vector<std::uint8_t>>& telegram) {
  const auto view = std::span<const std::uint8_t>(buffer_).subspan(start_);
  const framing::FrameScan scan = format_.scan(view);
  // A format answering with a size it cannot have seen is broken; treating
  // its front byte as noise keeps the reader moving.
  const bool size_fits = scan.length >= 1 && scan.length <= view.size();
  switch (scan.kind) {
    case framing::FrameScan::Kind::frame:
      if (!size_fits) break;
      telegram.emplace(view.begin(), view.begin() + static_cast<std::ptrdiff_t>(scan.length));
      start_ += scan.length;
      wanted_ = 0;
      in_noise_ = false;
      link_.counters().telegrams.add();
      return Verdict::telegram;
    case framing::FrameScan::Kind::bad_checksum:
      if (!size_fits) break;
      link_.counters().checksum_errors.add();
      drop_front(1, false);
      // The rest of the bad telegram is dropped as part of this error, not
      // counted again as a resync.
      in_noise_ = true;
      return Verdict::dropped;
    case framing::FrameScan::Kind::skip:
      drop_front(std::clamp<std::size_t>(scan.length, 1, view.size()), true);
      return Verdict::dropped;
    case framing::FrameScan::Kind::need_more:
      if (scan.length > max_telegram_ || view.size() >= max_telegram_) break;  // a bogus length: never wait on it
      wanted_ = std::max(scan.length, view.size() + 1);
      return Verdict::need_more;
  }
  drop_front(1, true);
  return Verdict::dropped;
}

void FramedReader::drop_front(std::size_t count, bool noise) {
  if (noise && !in_noise_) link_.counters().resyncs.add();
  if (noise) in_noise_ = true;
  link_.counters().bytes_dropped.add(count);
  start_ += count;
  wanted_ = 0;
}

void FramedReader::fill(std::size_t wanted_total, Deadline deadline, bool& timed_out) {
  if (start_ == buffer_.size()) {
    buffer_.clear();
    start_ = 0;
  } else if (start_ >= kReadChunk && start_ * 2 >= buffer_.size()) {
    buffer_.erase(buffer_.begin(), buffer_.begin() + static_cast<std::ptrdiff_t>(start_));
    start_ = 0;
  }
  const std::size_t have = buffer_.size();
  const std::size_t missing = wanted_total > buffered() ? wanted_total - buffered() : 0;
  const std::size_t chunk = std::max(kReadChunk, missing);
  buffer_.resize(have + chunk);
  std::size_t count = 0;
  try {
    count = link_.read_some(std::span<std::uint8_t>(buffer_).subspan(have), deadline);
  } catch (...) {
    buffer_.resize(have);
    throw;
  }
  buffer_.resize(have + count);
  timed_out = count == 0;
}

void FramedReader::flush() {
  link_.counters().bytes_dropped.add(buffered());
  buffer_.clear();
  start_ = 0;
  wanted_ = 0;
  in_noise_ = false;
  link_.flush_input();
}

}  // namespace playerkit::links
