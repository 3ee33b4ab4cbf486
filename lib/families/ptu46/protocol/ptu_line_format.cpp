#include "families/ptu46/protocol/ptu_line_format.hpp"

namespace playerkit::hardware::ptu46 {

framing::LineOptions reply_line_options() {
  return {.end = framing::LineEnd::cr_or_lf,
          .max_length = kLongestReplyLine,
          .prompt = std::nullopt,
          .skip_empty_lines = true,
          .name = "ptu46"};
}

std::optional<Reply> parse_reply_after_echo(std::string_view line) {
  // The reply starts at the first '*' or '!' that begins one: behind the
  // echo of its command ("pr * 185.1428"), or behind line noise.
  for (std::size_t at = line.find_first_of("*!"); at != std::string_view::npos;
       at = line.find_first_of("*!", at + 1)) {
    if (auto reply = parse_reply(line.substr(at))) return reply;
  }
  return std::nullopt;
}

}  // namespace playerkit::hardware::ptu46
