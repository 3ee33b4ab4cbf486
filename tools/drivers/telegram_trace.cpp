#include "telegram_trace.hpp"

#include <algorithm>
#include <mutex>
#include <utility>

#include "links/trace_format.hpp"

namespace playerkit::player_drivers {

namespace {

using Kind = TracePiece::Kind;

std::vector<std::uint8_t> take_front(std::vector<std::uint8_t>& buffer, std::size_t count) {
  std::vector<std::uint8_t> front(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(count));
  buffer.erase(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(count));
  return front;
}

void add_noise(std::vector<TracePiece>& pieces, std::vector<std::uint8_t> bytes) {
  if (!pieces.empty() && pieces.back().kind == Kind::noise) {
    pieces.back().bytes.insert(pieces.back().bytes.end(), bytes.begin(), bytes.end());
  } else {
    pieces.push_back({Kind::noise, std::move(bytes)});
  }
}

}  // namespace

TelegramSplitter::TelegramSplitter(std::shared_ptr<const framing::FrameFormat> format) : format_(std::move(format)) {}

std::vector<TracePiece> TelegramSplitter::feed(std::span<const std::uint8_t> bytes) {
  std::vector<TracePiece> pieces;
  if (!format_) {
    if (!bytes.empty()) pieces.push_back({Kind::raw, {bytes.begin(), bytes.end()}});
    return pieces;
  }
  buffer_.insert(buffer_.end(), bytes.begin(), bytes.end());
  while (!buffer_.empty()) {
    const framing::FrameScan scan = format_->scan(buffer_);
    const std::size_t length = std::min(scan.length, buffer_.size());
    if (scan.kind == framing::FrameScan::Kind::need_more) break;
    if (scan.kind == framing::FrameScan::Kind::frame) {
      pieces.push_back({Kind::telegram, take_front(buffer_, length)});
    } else if (scan.kind == framing::FrameScan::Kind::bad_checksum) {
      pieces.push_back({Kind::bad_checksum, take_front(buffer_, length)});
    } else {
      add_noise(pieces, take_front(buffer_, std::max<std::size_t>(1, length)));
    }
  }
  return pieces;
}

std::vector<TracePiece> TelegramSplitter::flush() {
  std::vector<TracePiece> pieces;
  if (!buffer_.empty()) pieces.push_back({Kind::noise, std::exchange(buffer_, {})});
  return pieces;
}

core::ByteTrace telegram_trace(std::string label, families::TraceFraming framing,
                               std::function<void(std::string_view line)> sink) {
  struct State {
    State(std::string label_text, std::function<void(std::string_view)> line_sink, families::TraceFraming formats)
        : label(std::move(label_text)),
          sink(std::move(line_sink)),
          outgoing(std::move(formats.outgoing)),
          incoming(std::move(formats.incoming)) {}
    std::string label;
    std::function<void(std::string_view)> sink;
    TelegramSplitter outgoing;
    TelegramSplitter incoming;
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    std::mutex mutex;
  };
  auto state = std::make_shared<State>("trace " + std::move(label), std::move(sink), std::move(framing));
  return [state](bool outgoing, std::span<const std::uint8_t> bytes, std::chrono::steady_clock::time_point when) {
    const std::lock_guard lock(state->mutex);
    auto& splitter = outgoing ? state->outgoing : state->incoming;
    for (const TracePiece& piece : splitter.feed(bytes)) {
      std::string line = links::format_trace_line(state->label, outgoing ? links::Direction::out : links::Direction::in,
                                                  piece.bytes, when - state->start);
      if (piece.kind == Kind::bad_checksum) line += "  (bad checksum)";
      if (piece.kind == Kind::noise) line += "  (not a telegram)";
      state->sink(line);
    }
  };
}

}  // namespace playerkit::player_drivers
