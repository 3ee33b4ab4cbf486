#include "links/trace_format.hpp"

#include <cstdio>
#include <memory>
#include <mutex>
#include <utility>

namespace playerkit::links {

std::string hex_bytes(std::span<const std::uint8_t> bytes) {
  static constexpr char kDigits[] = "0123456789ABCDEF";
  std::string text;
  text.reserve(bytes.size() * 3);
  for (const std::uint8_t byte : bytes) {
    if (!text.empty()) text += ' ';
    text += kDigits[byte >> 4];
    text += kDigits[byte & 0x0F];
  }
  return text;
}

std::string format_trace_line(std::string_view label, Direction direction, std::span<const std::uint8_t> bytes,
                              LinkClock::duration since_start) {
  const double seconds = std::chrono::duration<double>(since_start).count();
  char time[32];
  std::snprintf(time, sizeof time, "%12.6f", seconds);
  return std::string(label) + " " + time + (direction == Direction::out ? " > " : " < ") + hex_bytes(bytes);
}

TraceHook hex_trace_hook(std::string label, std::function<void(std::string_view line)> sink) {
  struct State {
    std::string label;
    std::function<void(std::string_view)> sink;
    LinkClock::time_point start = LinkClock::now();
    std::mutex mutex;
  };
  auto state = std::make_shared<State>();
  state->label = std::move(label);
  state->sink = std::move(sink);
  return [state](Direction direction, std::span<const std::uint8_t> bytes, LinkClock::time_point when) {
    const std::string line = format_trace_line(state->label, direction, bytes, when - state->start);
    const std::lock_guard lock(state->mutex);
    state->sink(line);
  };
}

}  // namespace playerkit::links
