#pragma once
// NMEA 0183 sentences: `$` (or `!` for encapsulated data such as AIS), the
// body, `*` and two hex digits of checksum, CR LF. The checksum is the XOR of
// the bytes between the start character and the `*` (garminnmea.md §1).
//
// The telegram is the whole sentence from `$` through LF. A bare LF ending
// is accepted too: logs and some receivers drop the CR, and the body still
// ends at the `*`.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framing/frame_format.hpp"

namespace playerkit::framing {

struct NmeaOptions {
  // A sentence without `*hh`: the standard makes the checksum optional for
  // some sentences and gpsd accepts such sentences, so a driver may too.
  // When false, such a sentence is reported as bad_checksum.
  bool accept_missing_checksum = false;
  // The longest sentence, `$` through LF. The standard says 82 characters;
  // real receivers exceed it a little (proprietary sentences, extra decimal
  // places), so the default leaves room. Past it a sentence lost its end and
  // the reader resynchronises at the next `$`; at 4800 baud a lost LF costs
  // at most this many bytes, about a quarter of a second.
  std::size_t max_length = 128;
};

class NmeaFormat final : public FrameFormat {
 public:
  explicit NmeaFormat(NmeaOptions options = {});

  [[nodiscard]] std::string_view name() const override { return "nmea"; }
  [[nodiscard]] FrameScan scan(std::span<const std::uint8_t> buffered) const override;

 private:
  NmeaOptions options_;
};

// XOR of every byte of `body` (the text between `$` and `*`).
[[nodiscard]] std::uint8_t nmea_checksum(std::string_view body);

// `$` + body + `*` + two upper-case hex digits + CR LF. `start` is '$' or '!'.
[[nodiscard]] std::vector<std::uint8_t> nmea_sentence(std::string_view body, char start = '$');

// The body of a telegram NmeaFormat accepted: between the start character
// and the `*` (or the line end when the sentence has no checksum), e.g.
// "GPGGA,123519,...,M,,". Points into `sentence`.
[[nodiscard]] std::string_view nmea_body(std::span<const std::uint8_t> sentence);

}  // namespace playerkit::framing
