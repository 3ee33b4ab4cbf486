#include "families/trogdor/protocol/trogdor_reply_format.hpp"

#include <algorithm>

#include "families/trogdor/protocol/trogdor_messages.hpp"

namespace playerkit::hardware::trogdor {

namespace {

using framing::FrameScan;

FrameScan ack_and_block(std::span<const std::uint8_t> buffered, std::size_t block) {
  const std::size_t size = 1 + block;
  if (buffered.size() < size) return FrameScan::need(size);
  return xor_checks(buffered.subspan(1, block)) ? FrameScan::whole(size) : FrameScan::corrupt(size);
}

}  // namespace

FrameScan TrogdorReplyFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return FrameScan::need();
  if (buffered[0] == kNack) return FrameScan::whole(1);
  if (buffered[0] != kAck) {
    const auto next = std::find_if(buffered.begin() + 1, buffered.end(),
                                   [](std::uint8_t byte) { return byte == kAck || byte == kNack; });
    return FrameScan::noise(static_cast<std::size_t>(next - buffered.begin()));
  }
  switch (shape_) {
    case ReplyShape::ack:
      return FrameScan::whole(1);
    case ReplyShape::ack_then_odometry:
      return ack_and_block(buffered, kOdometryBlockSize);
    case ReplyShape::ack_then_voltage:
      return ack_and_block(buffered, kVoltageBlockSize);
    case ReplyShape::guess:
      for (const std::size_t block : {kOdometryBlockSize, kVoltageBlockSize}) {
        if (buffered.size() >= 1 + block && xor_checks(buffered.subspan(1, block))) return FrameScan::whole(1 + block);
      }
      return FrameScan::whole(1);
  }
  return FrameScan::whole(1);
}

FrameScan TrogdorHostFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.empty()) return FrameScan::need();
  const std::size_t size = host_message_size(buffered[0]);
  if (size == 0) return FrameScan::noise(1);
  if (buffered.size() < size) return FrameScan::need(size);
  if (buffered[0] == message::init[0]) {
    return std::equal(std::begin(message::init), std::end(message::init), buffered.begin()) ? FrameScan::whole(size)
                                                                                            : FrameScan::noise(1);
  }
  if (size == kWheelPairMessageSize && !xor_checks(buffered.first(size))) return FrameScan::corrupt(size);
  return FrameScan::whole(size);
}

}  // namespace playerkit::hardware::trogdor
