#include "framing/fixed_length_format.hpp"

#include <algorithm>
#include <utility>

namespace playerkit::framing {

FixedLengthFormat::FixedLengthFormat(FixedLengthOptions options) : options_(std::move(options)) {
  // A sync pattern longer than the telegram could never be found whole in one.
  options_.size = std::max({options_.size, options_.sync.size(), std::size_t{1}});
}

FrameScan FixedLengthFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return FrameScan::need(options_.size);
  const auto& sync = options_.sync;
  if (!sync.empty()) {
    // Compare what is buffered of the pattern; a mismatch drops bytes up to
    // the next possible start, so a pattern that begins inside the bad one is still found.
    const std::size_t known = std::min(sync.size(), buffered.size());
    if (!std::equal(sync.begin(), sync.begin() + static_cast<long>(known), buffered.begin())) {
      const auto next = std::find(buffered.begin() + 1, buffered.end(), sync.front());
      return FrameScan::noise(static_cast<std::size_t>(next - buffered.begin()));
    }
  }
  if (buffered.size() < options_.size) return FrameScan::need(options_.size);
  const auto telegram = buffered.first(options_.size);
  if (options_.check && !options_.check(telegram)) return FrameScan::corrupt(options_.size);
  return FrameScan::whole(options_.size);
}

}  // namespace playerkit::framing
