#pragma once
// Fixed-size binary records whose first byte alone has a marker bit set:
// the Ascension Flock of Birds' "phasing bit" (flockofbirds.md §1): bit 7 is
// 1 in a record's first byte and 0 in every other, the data travelling in
// the low 7 bits. A marked byte inside a record means that record was cut
// short; the search resumes there.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "framing/frame_format.hpp"

namespace playerkit::framing {

struct PhasingBitOptions {
  // Bytes per record: 12 for the Flock's POSITION/ANGLES records.
  std::size_t record_size = 12;
  std::uint8_t phasing_mask = 0x80;
  std::string name = "phasing";
};

class PhasingBitFormat final : public FrameFormat {
 public:
  explicit PhasingBitFormat(PhasingBitOptions options = {});

  [[nodiscard]] std::string_view name() const override { return options_.name; }
  [[nodiscard]] FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  [[nodiscard]] bool marked(std::uint8_t byte) const { return (byte & options_.phasing_mask) != 0; }

  PhasingBitOptions options_;
};

}  // namespace playerkit::framing
