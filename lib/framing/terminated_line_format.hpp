#pragma once
// Text lines: what Khepera, REB, PTU-46, CMUcam2 and the kit's test families
// speak. A telegram is one line **with its terminator** (so a trace shows
// what came over the wire, and a driver that cares can see which end a
// device used); `line_text()` gives the text without it.
//
// The serial line is always raw (lib/links/README.md): this format does the
// splitting a canonical-mode tty did for the reference drivers, with a bound,
// so a reply that lacks its terminator times out instead of hanging.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "framing/frame_format.hpp"

namespace playerkit::framing {

enum class LineEnd {
  lf,        // "\n" (Khepera commands, the kit's test families)
  cr,        // "\r" (CMUcam2, REB commands)
  crlf,      // "\r\n" only; a lone CR or LF is text (NMEA-like devices)
  cr_or_lf,  // either ends a line, a CR LF pair counting as one end (Khepera and REB replies, PTU-46)
};

struct LineOptions {
  LineEnd end = LineEnd::lf;
  // The longest line, terminator included. A longer run without a terminator
  // is noise: the reader drops it and resynchronises at the next line.
  std::size_t max_length = 256;
  // A byte that, at the start of a line, is a telegram of its own with no
  // terminator: the CMUcam2's idle prompt ':' (cmucam2.md §2.2).
  std::optional<std::uint8_t> prompt;
  // Lines holding only their terminator are dropped as noise instead of
  // being telegrams (the CR LF a Khepera driver sends at start-up).
  bool skip_empty_lines = false;
  // For traces and counters.
  std::string name = "line";
};

class TerminatedLineFormat final : public FrameFormat {
 public:
  explicit TerminatedLineFormat(LineOptions options = {});

  [[nodiscard]] std::string_view name() const override { return options_.name; }
  [[nodiscard]] FrameScan scan(std::span<const std::uint8_t> buffered) const override;
  [[nodiscard]] const LineOptions& options() const { return options_; }

 private:
  // Where the first line end in `buffered` begins and how long it is; nullopt if none yet.
  struct End {
    std::size_t at;
    std::size_t size;
  };
  [[nodiscard]] std::optional<End> find_end(std::span<const std::uint8_t> buffered) const;

  LineOptions options_;
};

// A telegram's text without its terminator: one trailing "\r\n", "\n" or
// "\r" is removed (whichever is there; a prompt has none). The view points
// into `telegram`.
[[nodiscard]] std::string_view line_text(std::span<const std::uint8_t> telegram);

// `text` followed by the terminator of `end`; cr_or_lf writes "\r\n", which
// every reader in that mode takes as one end.
[[nodiscard]] std::vector<std::uint8_t> line_bytes(std::string_view text, LineEnd end);

}  // namespace playerkit::framing
