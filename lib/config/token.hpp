#pragma once
// The tokens of the config-file language (server-behaviour.md §9.1).

#include <string>

#include "config/source_location.hpp"

namespace playerkit::config {

enum class TokenKind {
  Word,          // laser:0, driver, robot:6666:bob, a.b
  Number,        // a run of + - . 0-9, kept as written
  String,        // "..." on one line; text holds the contents without the quotes
  OpenParen,     // (
  CloseParen,    // )
  OpenBracket,   // [ starting a tuple
  CloseBracket,  // ]
  Newline,       // significant: a property's value must be on its name's line
  EndOfFile,
};

struct Token {
  TokenKind kind = TokenKind::EndOfFile;
  std::string text;
  SourceLocation where;

  friend bool operator==(const Token&, const Token&) = default;
};

// How error messages name a token: "word 'foo'", "number '1.5'", "string \"x\"",
// "'('", "newline", "end of file".
std::string describe(const Token& token);

}  // namespace playerkit::config
