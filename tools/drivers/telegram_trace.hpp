#pragma once
// `run --trace`: every byte a driver's link moves, one line per telegram,
// cut by the device's own framing (P2OS, SICK) and timestamped:
//
//   trace laser:0     0.012345 > 02 00 0A 00 20 00 53 49 43 4B 5F 4C 4D 53 B6 4E
//   trace laser:0     0.031002 < 06  (not a telegram)
//   trace laser:0     0.031410 < 02 80 03 00 A0 00 10 16 0A
//
// Reads arrive in arbitrary pieces; a telegram split over several reads is
// printed once it is whole. Links of other protocols print each read and
// write as it came.

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/driver.hpp"
#include "families/family_spec.hpp"
#include "framing/frame_format.hpp"

namespace playerkit::player_drivers {

struct TracePiece {
  enum class Kind { telegram, bad_checksum, noise, raw };
  Kind kind = Kind::raw;
  std::vector<std::uint8_t> bytes;
  friend bool operator==(const TracePiece&, const TracePiece&) = default;
};

// Splits one direction's bytes into telegrams with `format` (null: every
// chunk is a raw piece as it came). Noise between telegrams is one piece
// per run. Pure.
class TelegramSplitter {
 public:
  explicit TelegramSplitter(std::shared_ptr<const framing::FrameFormat> format);
  std::vector<TracePiece> feed(std::span<const std::uint8_t> bytes);
  // Whatever is left (an unfinished telegram), as noise.
  std::vector<TracePiece> flush();

 private:
  std::shared_ptr<const framing::FrameFormat> format_;
  std::vector<std::uint8_t> buffer_;
};

// A core::ByteTrace printing lines through `sink` (called under a lock, one
// line at a time, no newline), labelled `label`, times from the trace's creation.
core::ByteTrace telegram_trace(std::string label, families::TraceFraming framing,
                               std::function<void(std::string_view line)> sink);

}  // namespace playerkit::player_drivers
