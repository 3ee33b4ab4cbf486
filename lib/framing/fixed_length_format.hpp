#pragma once
// Telegrams of one fixed size: an ER1 command, a Trogdor odometry reply
// behind its ACK byte. Optionally every telegram starts with a sync pattern
// (the reader hunts for it) and carries a check the protocol defines (a
// callback, since each protocol has its own sum or XOR and its place).

#include <cstddef>
#include <cstdint>
#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framing/frame_format.hpp"

namespace playerkit::framing {

struct FixedLengthOptions {
  // The telegram's size, sync pattern and check included (at least 1).
  std::size_t size = 1;
  // Bytes every telegram starts with; empty: any byte may start one, and
  // only the check (if any) tells a telegram from noise.
  std::vector<std::uint8_t> sync;
  // True when a whole telegram passes the protocol's check; empty: no check.
  std::function<bool(std::span<const std::uint8_t>)> check;
  // For traces and counters.
  std::string name = "fixed";
};

class FixedLengthFormat final : public FrameFormat {
 public:
  explicit FixedLengthFormat(FixedLengthOptions options);

  [[nodiscard]] std::string_view name() const override { return options_.name; }
  [[nodiscard]] FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  FixedLengthOptions options_;
};

}  // namespace playerkit::framing
