// Bytes of a Player connection, cut into chunks as a socket might deliver
// them, through protocol::FrameReader; every whole message is decoded the
// way player-cat prints it (message_to_json), and its payload once more by a
// codec of the catalog chosen by the input, so every payload decoder is
// reached whatever the header says. A payload a codec decodes must come back
// from its own JSON (decode -> JSON -> encode -> decode gives the same JSON).
//
// Input: byte 0 seeds the chunk sizes, byte 1 picks the reader's payload
// limit, bytes 2-3 pick the codec; the rest is the stream.

#include <variant>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "protocol/catalog.hpp"
#include "protocol/errors.hpp"
#include "protocol/frame_reader.hpp"
#include "protocol/message_json.hpp"

namespace playerkit::fuzz {
namespace frame_reader_detail {

using protocol::PayloadCodec;

// The codecs of the catalog in a fixed order: each interface's data and
// command struct, then each request's struct and reply.
std::vector<const PayloadCodec*> all_codecs() {
  std::vector<const PayloadCodec*> codecs;
  for (const auto& messages : protocol::all_messages()) {
    if (messages.data) codecs.push_back(messages.data);
    if (messages.command) codecs.push_back(messages.command);
    for (const auto& kind : messages.requests) {
      if (kind.request) codecs.push_back(kind.request);
      if (kind.reply) codecs.push_back(kind.reply);
    }
  }
  return codecs;
}

void check_codec(const PayloadCodec& codec, std::span<const std::uint8_t> payload) {
  nlohmann::json decoded;
  try {
    decoded = codec.to_json(payload);
  } catch (const protocol::DecodeError&) {
    return;  // bytes that are not this struct: refused, as documented
  }
  // What a codec decoded, it must encode again and read back the same; a
  // JsonError or EncodeError here escapes as a finding.
  const std::vector<std::uint8_t> encoded = codec.from_json(decoded);
  if (encoded.size() < codec.min_size || encoded.size() > codec.max_size) {
    invariant_failed("frame_reader", "an encoded payload outside its codec's size range");
  }
  if (codec.to_json(encoded) != decoded) {
    invariant_failed("frame_reader", "decode(encode(decode(payload))) differs from decode(payload)");
  }
}

void check_message(const protocol::Message& message) {
  nlohmann::json j;
  try {
    j = protocol::message_to_json(message);
  } catch (const protocol::DecodeError&) {
    return;
  }
  try {
    (void)protocol::message_from_json(j);
  } catch (const protocol::JsonError&) {
    // The header's fields may name no known type or device; documented.
  } catch (const protocol::EncodeError&) {
  }
}

}  // namespace frame_reader_detail

int frame_reader(const std::uint8_t* data, std::size_t size) {
  using namespace frame_reader_detail;
  static const std::vector<const PayloadCodec*> codecs = all_codecs();
  ByteSource in(data, size);
  std::uint32_t chunk_state = in.byte() | 1u;
  const std::size_t max_payload =
      (in.byte() & 1) != 0 ? protocol::kMaxPayloadSize : std::size_t{64} << 10;
  const std::size_t codec_choice = std::size_t{in.byte()} << 8 | in.byte();
  const PayloadCodec& codec = *codecs[codec_choice % codecs.size()];

  const auto stream = in.rest();
  protocol::FrameReader reader(max_payload);
  std::size_t fed = 0;
  std::size_t delivered = 0;
  while (!in.empty()) {
    // xorshift: chunk sizes from 1 to 64 bytes, repeatable from byte 0.
    chunk_state ^= chunk_state << 13;
    chunk_state ^= chunk_state >> 17;
    chunk_state ^= chunk_state << 5;
    const auto chunk = in.take(1 + chunk_state % 64);
    fed += chunk.size();
    for (const auto& event : reader.feed(chunk)) {
      if (const auto* message = std::get_if<protocol::Message>(&event)) {
        delivered += protocol::kHeaderSize + message->payload.size();
        if (message->payload.size() > max_payload) {
          invariant_failed("frame_reader", "a message above the reader's payload limit");
        }
        check_message(*message);
        check_codec(codec, message->payload);
      } else if (const auto* skipped = std::get_if<protocol::SkippedBytes>(&event)) {
        delivered += skipped->count;
      } else {
        delivered += protocol::kHeaderSize;
      }
    }
  }
  // Every byte fed is in a message, reported skipped, or still held (an
  // oversize body being discarded counts as its header only).
  if (delivered + reader.buffered() > fed) {
    invariant_failed("frame_reader", "more bytes reported than fed");
  }
  check_codec(codec, stream);
  return 0;
}

}  // namespace playerkit::fuzz
