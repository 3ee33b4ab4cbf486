#include "framing/phasing_bit_format.hpp"

#include <algorithm>
#include <utility>

namespace playerkit::framing {

PhasingBitFormat::PhasingBitFormat(PhasingBitOptions options) : options_(std::move(options)) {
  options_.record_size = std::max<std::size_t>(options_.record_size, 1);
  // With no marker bit nothing could ever start a record.
  if (options_.phasing_mask == 0) options_.phasing_mask = 0x80;
}

FrameScan PhasingBitFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return FrameScan::need(options_.record_size);
  if (!marked(buffered.front())) {
    const auto next = std::find_if(buffered.begin() + 1, buffered.end(), [this](std::uint8_t b) { return marked(b); });
    return FrameScan::noise(static_cast<std::size_t>(next - buffered.begin()));
  }
  const std::size_t known = std::min(buffered.size(), options_.record_size);
  for (std::size_t i = 1; i < known; ++i) {
    if (marked(buffered[i])) return FrameScan::noise(i);
  }
  if (buffered.size() < options_.record_size) return FrameScan::need(options_.record_size);
  return FrameScan::whole(options_.record_size);
}

}  // namespace playerkit::framing
