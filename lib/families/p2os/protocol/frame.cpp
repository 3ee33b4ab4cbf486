#include "families/p2os/protocol/frame.hpp"

#include "families/p2os/protocol/byte_cursor.hpp"
#include "families/p2os/protocol/errors.hpp"

#include <string>

namespace playerkit::hardware::p2os {

std::uint16_t checksum(std::span<const std::uint8_t> payload) {
  std::uint16_t sum = 0;
  std::size_t i = 0;
  for (; i + 1 < payload.size(); i += 2) {
    sum = static_cast<std::uint16_t>(sum + ((payload[i] << 8) | payload[i + 1]));
  }
  if (i < payload.size()) sum = static_cast<std::uint16_t>(sum ^ payload[i]);
  return sum;
}

std::vector<std::uint8_t> build_frame(std::span<const std::uint8_t> payload) {
  if (payload.empty()) throw EncodeError("P2OS frame: the payload is empty (it needs a type byte)");
  const std::size_t length = payload.size() + kChecksumSize;
  if (length > kMaxLengthByteFromRobot) {
    throw EncodeError("P2OS frame: payload of " + std::to_string(payload.size()) +
                      " bytes is too long (N would be " + std::to_string(length) + ", at most " +
                      std::to_string(kMaxLengthByteFromRobot) + ")");
  }
  std::vector<std::uint8_t> frame;
  frame.reserve(kHeaderSize + length);
  frame.push_back(kHeader1);
  frame.push_back(kHeader2);
  frame.push_back(static_cast<std::uint8_t>(length));
  frame.insert(frame.end(), payload.begin(), payload.end());
  const std::uint16_t sum = checksum(payload);
  frame.push_back(static_cast<std::uint8_t>(sum >> 8));
  frame.push_back(static_cast<std::uint8_t>(sum & 0xFF));
  return frame;
}

std::span<const std::uint8_t> frame_payload(std::span<const std::uint8_t> frame) {
  if (frame.size() < kHeaderSize + kMinLengthByte) {
    throw DecodeError("P2OS frame: " + std::to_string(frame.size()) +
                      " bytes are too few for a frame (at least 6)");
  }
  if (frame[0] != kHeader1 || frame[1] != kHeader2) {
    throw DecodeError("P2OS frame: does not start with FA FB");
  }
  const std::size_t length = frame[2];
  if (length < kMinLengthByte || frame.size() != kHeaderSize + length) {
    throw DecodeError("P2OS frame: length byte " + std::to_string(length) + " does not match the " +
                      std::to_string(frame.size()) + " bytes given");
  }
  const auto payload = frame.subspan(kHeaderSize, length - kChecksumSize);
  const std::uint16_t sent =
      static_cast<std::uint16_t>((frame[kHeaderSize + length - 2] << 8) | frame.back());
  if (sent != checksum(payload)) {
    throw DecodeError("P2OS frame: checksum " + detail::hex_byte(static_cast<std::uint8_t>(sent >> 8)) +
                      detail::hex_byte(static_cast<std::uint8_t>(sent & 0xFF)).substr(2) +
                      " does not match the payload");
  }
  return payload;
}

}  // namespace playerkit::hardware::p2os
