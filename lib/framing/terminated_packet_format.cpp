#include "framing/terminated_packet_format.hpp"

#include <algorithm>
#include <utility>

namespace playerkit::framing {

TerminatedPacketFormat::TerminatedPacketFormat(TerminatedPacketOptions options) : options_(std::move(options)) {
  // A packet is at least its header and terminator.
  options_.min_length = std::max<std::size_t>(options_.min_length, 2);
  options_.max_length = std::max(options_.max_length, options_.min_length);
}

FrameScan TerminatedPacketFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return FrameScan::need();
  if (!is_header(buffered.front())) {
    const auto next =
        std::find_if(buffered.begin() + 1, buffered.end(), [this](std::uint8_t b) { return is_header(b); });
    return FrameScan::noise(static_cast<std::size_t>(next - buffered.begin()));
  }
  const std::size_t limit = std::min(buffered.size(), options_.max_length);
  for (std::size_t i = 1; i < limit; ++i) {
    const std::uint8_t byte = buffered[i];
    if (byte == options_.terminator) {
      const std::size_t size = i + 1;
      // Too short to carry a message (`90 FF`): the header was noise.
      if (size < options_.min_length) return FrameScan::noise(1);
      return FrameScan::whole(size);
    }
    if (is_header(byte)) return FrameScan::noise(i);
  }
  if (buffered.size() >= options_.max_length) return FrameScan::noise(1);
  return FrameScan::need();
}

}  // namespace playerkit::framing
