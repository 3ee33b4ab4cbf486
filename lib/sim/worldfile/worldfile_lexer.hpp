#pragma once
// The tokens of Stage's world-file language (stage-worlds.md §1.1), read
// character by character as Stage's worldfile.cc does: the first character
// decides a token's kind. `include "file"` is handled here too, as in Stage,
// by splicing the named file's tokens in place (worldfile_includes.hpp reads
// the file).

#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "sim/worldfile/worldfile_location.hpp"

namespace playerkit::sim::worldfile {

enum class TokenKind {
  Word,        // a letter, then letters, digits, . - _ [ ]   (spose[3] is one word)
  Number,      // a run of + - . 0-9, kept as written (no exponent)
  String,      // "..." on one line; text is the contents without the quotes
  OpenEntity,  // (
  CloseEntity, // )
  OpenTuple,   // [
  CloseTuple,  // ]
  Comment,     // # to the end of the line (kept: a comment inside a tuple is an error)
  Newline,     // significant: a property's value and a tuple stay on one line
  EndOfFile,
};

struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  std::string text;
  SourceLocation where;
};

// How messages name a token: "the word \"foo\"", "the number 1.5",
// "the string \"x\"", "'('", "the end of the line", "the end of the file".
std::string describe(const Token& token);

// Called for `include "name"` with the string token; appends the included
// file's tokens (without its EndOfFile) to `out`.
using IncludeHandler = std::function<void(const Token& name, std::vector<Token>& out)>;

// Appends the tokens of `text` (the contents of `file`) to `out`, without an
// EndOfFile token, and returns where the text ends. Throws WorldFileError at
// the offending character.
SourceLocation tokenize(std::string_view text, const std::string& file, std::vector<Token>& out,
              const IncludeHandler& on_include);

}  // namespace playerkit::sim::worldfile
