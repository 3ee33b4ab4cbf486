#pragma once
// Splits a byte stream into Player messages, and survives garbage. The server
// reads its clients with it, clients read the server.
//
// Bytes go in as they arrive; whole messages come out. A stream that does not
// start with the "Xx" marker is scanned forward to the next marker (the bytes
// skipped are reported once per run). A header announcing more than the
// largest payload a 1.5 client can send is reported and its body skipped, so
// the connection stays usable; an absurd size (beyond kMaxSkippableSize) is
// treated as garbage and scanned past instead, so a corrupt header cannot make
// us swallow the rest of the stream.

#include <cstddef>
#include <cstdint>
#include <span>
#include <variant>
#include <vector>

#include "protocol/message.hpp"

namespace playerkit::protocol {

struct SkippedBytes {
  std::size_t count = 0;
};

struct OversizeMessage {
  MessageHeader header;  // its body is discarded
};

using FrameEvent = std::variant<Message, SkippedBytes, OversizeMessage>;

class FrameReader {
 public:
  static constexpr std::size_t kMaxSkippableSize = 1 << 20;

  // Payloads above max_payload are reported as OversizeMessage. The server
  // keeps 1.5's limit for what clients send; a client reading the server
  // allows more (camera images are larger).
  explicit FrameReader(std::size_t max_payload = kMaxPayloadSize) : max_payload_(max_payload) {}

  // Appends the bytes and returns every event they complete, in stream order.
  std::vector<FrameEvent> feed(std::span<const std::uint8_t> bytes);

  // Bytes held back waiting for the rest of a message.
  [[nodiscard]] std::size_t buffered() const { return buffer_.size() - start_; }

 private:
  void drop(std::size_t count);
  void flush_skipped(std::vector<FrameEvent>& events);

  std::size_t max_payload_;
  std::vector<std::uint8_t> buffer_;
  std::size_t start_ = 0;            // first unconsumed byte of buffer_
  std::size_t body_to_discard_ = 0;  // rest of an oversize message
  std::size_t skipped_ = 0;          // garbage in the current run
};

}  // namespace playerkit::protocol
