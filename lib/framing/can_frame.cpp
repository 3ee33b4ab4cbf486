#include "framing/can_frame.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace playerkit::framing {

std::array<std::uint8_t, kCanRecordSize> encode_can_frame(const CanFrame& frame) {
  const std::uint32_t id_mask = frame.extended ? kCanExtendedIdMask : kCanStandardIdMask;
  if ((frame.id & ~id_mask) != 0) {
    throw std::invalid_argument("CAN id " + std::to_string(frame.id) + " does not fit in " +
                                (frame.extended ? "29" : "11") + " bits");
  }
  if (frame.dlc > 8) throw std::invalid_argument("CAN dlc " + std::to_string(frame.dlc) + " is above 8");

  std::uint32_t can_id = frame.id;
  if (frame.extended) can_id |= kCanExtendedFlag;
  if (frame.remote) can_id |= kCanRemoteFlag;
  std::array<std::uint8_t, kCanRecordSize> record{};
  for (std::size_t i = 0; i < 4; ++i) record[i] = static_cast<std::uint8_t>(can_id >> (8 * i));
  record[4] = frame.dlc;
  // A remote frame carries no data whatever its dlc says.
  if (!frame.remote) std::copy_n(frame.data.begin(), frame.dlc, record.begin() + 8);
  return record;
}

std::optional<CanFrame> decode_can_frame(std::span<const std::uint8_t> record) {
  if (record.size() < kCanRecordSize) return std::nullopt;
  std::uint32_t can_id = 0;
  for (std::size_t i = 0; i < 4; ++i) can_id |= static_cast<std::uint32_t>(record[i]) << (8 * i);
  if ((can_id & kCanErrorFlag) != 0) return std::nullopt;

  CanFrame frame;
  frame.extended = (can_id & kCanExtendedFlag) != 0;
  frame.remote = (can_id & kCanRemoteFlag) != 0;
  frame.id = can_id & kCanExtendedIdMask;
  if (!frame.extended && frame.id > kCanStandardIdMask) return std::nullopt;
  frame.dlc = record[4];
  if (frame.dlc > 8) return std::nullopt;
  if (!frame.remote) std::copy_n(record.begin() + 8, frame.dlc, frame.data.begin());
  return frame;
}

FrameScan CanRecordFormat::scan(std::span<const std::uint8_t> buffered) const {
  if (buffered.size() < kCanRecordSize) return FrameScan::need(kCanRecordSize);
  if (!decode_can_frame(buffered.first(kCanRecordSize))) return FrameScan::noise(kCanRecordSize);
  return FrameScan::whole(kCanRecordSize);
}

}  // namespace playerkit::framing
