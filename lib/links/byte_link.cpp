#include "links/byte_link.hpp"

#include <utility>

#include "links/link_error.hpp"

namespace playerkit::links {

std::size_t ByteLink::read_some(std::span<std::uint8_t> buffer, Deadline deadline) {
  const std::size_t count = read_available(buffer, deadline);
  if (count > 0) report(Direction::in, buffer.first(count));
  return count;
}

void ByteLink::write_all(std::span<const std::uint8_t> bytes, Deadline deadline) {
  std::size_t written = 0;
  while (written < bytes.size()) {
    const std::size_t count = write_available(bytes.subspan(written), deadline);
    if (count == 0) break;
    report(Direction::out, bytes.subspan(written, count));
    written += count;
  }
  if (written < bytes.size()) {
    counters_.timeouts.add();
    throw LinkError(LinkErrorKind::timed_out, describe(),
                    describe() + ": write timed out after " + std::to_string(written) + " of " +
                        std::to_string(bytes.size()) + " bytes (flow control holding the line, or nobody reading)");
  }
}

bool ByteLink::set_baud(int /*baud*/) { return false; }

void ByteLink::set_trace_hook(TraceHook hook) {
  auto shared = hook ? std::make_shared<const TraceHook>(std::move(hook)) : nullptr;
  const std::lock_guard lock(trace_mutex_);
  trace_hook_ = std::move(shared);
}

void ByteLink::report(Direction direction, std::span<const std::uint8_t> bytes) {
  if (bytes.empty()) return;
  (direction == Direction::in ? counters_.bytes_in : counters_.bytes_out).add(bytes.size());
  std::shared_ptr<const TraceHook> hook;
  {
    const std::lock_guard lock(trace_mutex_);
    hook = trace_hook_;
  }
  if (hook) (*hook)(direction, bytes, LinkClock::now());
}

}  // namespace playerkit::links
