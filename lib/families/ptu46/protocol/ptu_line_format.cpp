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
  if (auto reply = parse_reply(line)) return reply;
  // An echoed command is letters, digits and a sign, then its delimiter.
  const std::size_t start = line.find_first_of("*!");
  if (start == std::string_view::npos || start == 0 || line[start - 1] != ' ') return std::nullopt;
  return parse_reply(line.substr(start));
}

}  // namespace playerkit::hardware::ptu46
