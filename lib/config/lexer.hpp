#pragma once
// Splits the text of one config file into tokens (server-behaviour.md §9.1).
// Includes are not followed here; see includes.hpp.

#include <string>
#include <string_view>
#include <vector>

#include "config/token.hpp"

namespace playerkit::config {

// Returns every token of `text` in order, comments dropped, ending with one
// EndOfFile token. `file` only labels the locations. "\r\n" and a lone "\r"
// count as one line break. Throws ConfigError on a character that starts no
// token and on a string that is not closed on its line.
std::vector<Token> tokenize(std::string_view text, const std::string& file);

}  // namespace playerkit::config
