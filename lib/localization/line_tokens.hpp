#pragma once
// The whitespace-separated tokens of one log line with their byte offsets, so
// that a token can be read as a number or replaced in place (the rest of the
// line kept byte for byte). Internal to lib/localization.

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace playerkit::localization {

struct LineToken {
  std::size_t offset = 0;  // byte offset in the line
  std::string_view text;
};

std::vector<LineToken> split_line_tokens(std::string_view line);

// The token as a number ("+01.250" and "1.13486e+09" alike). Throws
// std::runtime_error naming `what` when it is not one.
double token_number(const LineToken& token, std::string_view what);

// Replaces tokens [first, first + replacements.size()) of `line` with
// `replacements`, keeping every other byte. `tokens` must be those of `line`.
std::string replace_tokens(std::string_view line, const std::vector<LineToken>& tokens, std::size_t first,
                           const std::vector<std::string>& replacements);

// printf-style into a std::string.
std::string format_text(const char* format, double value);

}  // namespace playerkit::localization
