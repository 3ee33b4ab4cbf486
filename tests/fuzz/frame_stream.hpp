#pragma once
// A byte stream cut into telegrams by a framing::FrameFormat, the way the
// drivers' framed readers and the emulators' parsers use one, checking the
// contract of lib/framing/frame_format.hpp on every answer: lengths within what
// is buffered, at least one byte skipped, a need_more that asks for more.

#include <cstdint>
#include <span>
#include <vector>

#include "fuzz_support.hpp"
#include "fuzz_targets.hpp"
#include "framing/frame_format.hpp"

namespace playerkit::fuzz {

// Calls on_frame(telegram, checksum_ok) for every telegram of `stream`, fed
// in chunks of 1 to 32 bytes drawn from `chunk_seed`.
template <class OnFrame>
void split_frames(const char* target, const framing::FrameFormat& format,
                  std::span<const std::uint8_t> stream, std::uint8_t chunk_seed, OnFrame on_frame) {
  using Kind = framing::FrameScan::Kind;
  std::vector<std::uint8_t> buffer;
  ByteSource in(stream.data(), stream.size());
  std::uint32_t state = chunk_seed | 1u;
  while (!in.empty()) {
    state ^= state << 13;
    state ^= state >> 17;
    state ^= state << 5;
    const auto chunk = in.take(1 + state % 32);
    buffer.insert(buffer.end(), chunk.begin(), chunk.end());
    while (!buffer.empty()) {
      const framing::FrameScan scan = format.scan(buffer);
      if (scan.kind == Kind::need_more) {
        if (scan.length != 0 && scan.length <= buffer.size()) {
          invariant_failed(target, "need_more for a size already buffered");
        }
        break;
      }
      if (scan.length == 0 || scan.length > buffer.size()) {
        invariant_failed(target, "a frame or skip length of 0 or beyond the buffered bytes");
      }
      if (scan.kind != Kind::skip) {
        on_frame(std::span<const std::uint8_t>(buffer.data(), scan.length), scan.kind == Kind::frame);
      }
      buffer.erase(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(scan.length));
    }
  }
}

}  // namespace playerkit::fuzz
