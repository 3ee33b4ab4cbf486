#pragma once
// How the PTU-46's replies are cut: lines ended by CR, LF or CR LF (the
// reference driver needed the LF; a real unit may end with CR alone).

#include <cstddef>
#include <optional>
#include <string_view>

#include "families/ptu46/protocol/ptu_replies.hpp"
#include "framing/terminated_line_format.hpp"

namespace playerkit::hardware::ptu46 {

// The longest reply worth waiting for: a verbose message with its echo.
inline constexpr std::size_t kLongestReplyLine = 160;

[[nodiscard]] framing::LineOptions reply_line_options();

// The reply in a line that may begin with the echo of its command (echo is
// on at power-up) or with noise: "pr * 185.1428" reads as "* 185.1428".
[[nodiscard]] std::optional<Reply> parse_reply_after_echo(std::string_view line);

}  // namespace playerkit::hardware::ptu46
