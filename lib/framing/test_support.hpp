#pragma once
// What the framing tests share: bytes from text or hex, and a stand-in for a
// reader that feeds a format a stream in pieces of a chosen size and keeps
// what it cut. Test code only.

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "framing/frame_format.hpp"

namespace playerkit::framing::test_support {

using Bytes = std::vector<std::uint8_t>;

inline Bytes text_bytes(std::string_view text) { return Bytes(text.begin(), text.end()); }

// "02 05 82": bytes written as in the device sheets.
inline Bytes hex(std::string_view text) {
  Bytes out;
  std::string digits;
  for (const char c : text) {
    if (c == ' ') continue;
    digits.push_back(c);
    if (digits.size() == 2) {
      out.push_back(static_cast<std::uint8_t>(std::stoul(digits, nullptr, 16)));
      digits.clear();
    }
  }
  EXPECT_TRUE(digits.empty()) << "odd number of hex digits in " << text;
  return out;
}

inline Bytes concat(std::initializer_list<Bytes> parts) {
  Bytes out;
  for (const auto& part : parts) out.insert(out.end(), part.begin(), part.end());
  return out;
}

// What a reader made of a stream.
struct Cut {
  std::vector<Bytes> frames;
  std::vector<Bytes> bad_checksums;
  std::size_t skipped = 0;
  std::size_t left_over = 0;  // buffered at the end, still waiting for more
};

// Feeds `stream` to `format` `piece` bytes at a time (1: byte by byte, the
// worst case for need_more logic) and acts on every scan as a reader would:
// a frame or a bad frame is taken whole, noise dropped. Also checks the
// contract: every verdict but need_more moves on by 1 to the buffered size,
// and a need_more's target lies beyond what is buffered.
inline Cut cut(const FrameFormat& format, const Bytes& stream, std::size_t piece = 1) {
  Cut result;
  Bytes buffer;
  for (std::size_t from = 0; from < stream.size(); from += piece) {
    const std::size_t to = std::min(stream.size(), from + piece);
    buffer.insert(buffer.end(), stream.begin() + static_cast<long>(from), stream.begin() + static_cast<long>(to));
    // Each verdict but need_more consumes at least a byte, so this ends.
    while (!buffer.empty()) {
      const FrameScan scan = format.scan(buffer);
      if (scan.kind == FrameScan::Kind::need_more) {
        if (scan.length != 0) EXPECT_GT(scan.length, buffer.size()) << format.name() << ": asks for bytes it has";
        break;
      }
      EXPECT_GE(scan.length, 1u) << format.name();
      EXPECT_LE(scan.length, buffer.size()) << format.name();
      if (scan.length == 0 || scan.length > buffer.size()) return result;
      const Bytes front(buffer.begin(), buffer.begin() + static_cast<long>(scan.length));
      if (scan.kind == FrameScan::Kind::frame) result.frames.push_back(front);
      if (scan.kind == FrameScan::Kind::bad_checksum) result.bad_checksums.push_back(front);
      if (scan.kind == FrameScan::Kind::skip) result.skipped += scan.length;
      buffer.erase(buffer.begin(), buffer.begin() + static_cast<long>(scan.length));
    }
  }
  result.left_over = buffer.size();
  return result;
}

}  // namespace playerkit::framing::test_support
